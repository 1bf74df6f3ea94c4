#include "bounded_stream.hpp"

#include <netdb.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace web_viewer {
namespace {

/// Whether `events` happen on `sock` within `timeout_ms`; a hang-up or error counts, so that
/// the following recv or send reports it.
bool wait_for(socket_t sock, short events, int timeout_ms) {
  pollfd entry{sock, events, 0};
  int ready = 0;
  do {
    ready = ::poll(&entry, 1, timeout_ms);
  } while (ready < 0 && errno == EINTR);
  return ready > 0;
}

/// The numeric address and port of a socket address.
void address_of(const sockaddr_storage& address, socklen_t length, std::string& ip, int& port) {
  char host[NI_MAXHOST] = "";
  const bool named = ::getnameinfo(reinterpret_cast<const sockaddr*>(&address), length, host,
                                   sizeof host, nullptr, 0, NI_NUMERICHOST) == 0;
  ip = named ? host : "";
  if (address.ss_family == AF_INET)
    port = ntohs(reinterpret_cast<const sockaddr_in&>(address).sin_port);
  else if (address.ss_family == AF_INET6)
    port = ntohs(reinterpret_cast<const sockaddr_in6&>(address).sin6_port);
  else
    port = 0;
}

}  // namespace

BoundedStream::BoundedStream(socket_t sock, int read_timeout_ms, int write_timeout_ms,
                             std::size_t head_limit, std::size_t body_limit,
                             int request_deadline_ms)
    : sock_(sock),
      read_timeout_ms_(read_timeout_ms),
      write_timeout_ms_(write_timeout_ms),
      head_limit_(head_limit),
      body_limit_(body_limit),
      request_deadline_ms_(request_deadline_ms) {}

void BoundedStream::begin_request() {
  in_head_ = true;
  given_ = 0;
  deadline_ = std::chrono::steady_clock::now() + std::chrono::milliseconds(request_deadline_ms_);
}

int BoundedStream::until_deadline_ms() const {
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
      deadline_ - std::chrono::steady_clock::now());
  return left.count() > 0 ? static_cast<int>(left.count()) : 0;
}

void BoundedStream::end_head() {
  in_head_ = false;
  given_ = 0;
}

bool BoundedStream::wait_readable(int timeout_ms) const {
  return has_buffered() || wait_for(sock_, POLLIN, timeout_ms);
}

bool BoundedStream::is_readable() const { return wait_readable(read_timeout_ms_); }

bool BoundedStream::is_writable() const { return wait_for(sock_, POLLOUT, write_timeout_ms_); }

ssize_t BoundedStream::fill(int timeout_ms) {
  if (!wait_for(sock_, POLLIN, timeout_ms)) return -1;
  ssize_t n = 0;
  do {
    n = ::recv(sock_, buffer_.data(), buffer_.size(), 0);
  } while (n < 0 && errno == EINTR);
  begin_ = 0;
  end_ = n > 0 ? static_cast<std::size_t>(n) : 0;
  return n;
}

ssize_t BoundedStream::read(char* ptr, size_t size) {
  const std::size_t limit = in_head_ ? head_limit_ : body_limit_;
  if (given_ >= limit) {
    exhausted_ = true;
    return 0;
  }
  if (!has_buffered()) {
    // A slow sender's request ends at its deadline, as at a bound: one line every few seconds
    // would otherwise hold a thread for as long as it likes.
    const int left_ms = until_deadline_ms();
    if (left_ms == 0) {
      exhausted_ = true;
      return 0;
    }
    const ssize_t received = fill(std::min(read_timeout_ms_, left_ms));
    if (received < 0 && until_deadline_ms() == 0) {
      exhausted_ = true;
      return 0;
    }
    if (received <= 0) return received;
  }
  const std::size_t n = std::min({size, end_ - begin_, limit - given_});
  std::memcpy(ptr, buffer_.data() + begin_, n);
  begin_ += n;
  given_ += n;
  return static_cast<ssize_t>(n);
}

ssize_t BoundedStream::write(const char* ptr, size_t size) {
  if (!is_writable()) return -1;
  ssize_t n = 0;
  do {
    n = ::send(sock_, ptr, size, MSG_NOSIGNAL);
  } while (n < 0 && errno == EINTR);
  return n;
}

void BoundedStream::get_remote_ip_and_port(std::string& ip, int& port) const {
  sockaddr_storage address{};
  socklen_t length = sizeof address;
  if (::getpeername(sock_, reinterpret_cast<sockaddr*>(&address), &length) == 0) {
    address_of(address, length, ip, port);
  }
}

void BoundedStream::get_local_ip_and_port(std::string& ip, int& port) const {
  sockaddr_storage address{};
  socklen_t length = sizeof address;
  if (::getsockname(sock_, reinterpret_cast<sockaddr*>(&address), &length) == 0) {
    address_of(address, length, ip, port);
  }
}

}  // namespace web_viewer
