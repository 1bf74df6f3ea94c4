#include "raw_client.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>

#include <gtest/gtest.h>

#include "child_process.hpp"
#include "moos/clock.hpp"
#include "wire_messages.hpp"

namespace moosdb_lite::test {

using namespace moos::test;

namespace {

using test_support::steady_now_s;

constexpr std::size_t kReadChunkBytes = 64 * 1024;

}  // namespace

double moos_now() { return moos::system_clock().unix_now_s(); }

RawClient::~RawClient() { close(); }

bool RawClient::connect(int port, int receive_buffer_bytes) {
  fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd_ < 0) return false;
  if (receive_buffer_bytes > 0)
    setsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &receive_buffer_bytes, sizeof receive_buffer_bytes);
  const int on = 1;
  setsockopt(fd_, IPPROTO_TCP, TCP_NODELAY, &on, sizeof on);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(static_cast<std::uint16_t>(port));
  inet_pton(AF_INET, "127.0.0.1", &addr.sin_addr);
  return ::connect(fd_, reinterpret_cast<const sockaddr*>(&addr), sizeof addr) == 0;
}

bool RawClient::send_bytes(std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t n = ::send(fd_, bytes.data(), bytes.size(), MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

std::optional<std::vector<moos::Message>> RawClient::handshake(const std::string& name, bool async,
                                                               double ident_time) {
  name_ = name;
  if (!send_bytes(moos::protocol_banner() +
                  moos::encode_packet({identification(name, async, ident_time)})))
    return std::nullopt;
  return read_packet();
}

bool RawClient::join(int port, const std::string& name, bool async) {
  if (!connect(port)) {
    ADD_FAILURE() << name << ": cannot connect to port " << port;
    return false;
  }
  const auto reply = handshake(name, async, moos_now());
  if (!reply || reply->empty() || reply->front().type != moos::msg_type::kWelcome) {
    ADD_FAILURE() << name << ": no WELCOME";
    return false;
  }
  return true;
}

std::optional<std::vector<moos::Message>> RawClient::read_packet(double timeout_s) {
  const double deadline = steady_now_s() + timeout_s;
  char buffer[kReadChunkBytes];
  for (;;) {
    std::vector<moos::Message> packet;
    moos::DecodeError error;
    const auto status = reader_.next(packet, &error);
    if (status == moos::PacketReader::Status::kPacket) return packet;
    if (status == moos::PacketReader::Status::kError) {
      ADD_FAILURE() << name_ << ": undecodable packet from the server: " << error.reason;
      return std::nullopt;
    }
    if (eof_) return std::nullopt;
    const double left_s = deadline - steady_now_s();
    if (left_s <= 0) return std::nullopt;
    pollfd pfd{fd_, POLLIN, 0};
    if (::poll(&pfd, 1, static_cast<int>(left_s * 1000) + 1) <= 0) continue;
    const ssize_t n = ::recv(fd_, buffer, sizeof buffer, 0);
    if (n > 0) {
      reader_.feed(std::string_view(buffer, static_cast<std::size_t>(n)));
    } else if (n == 0 || (errno != EINTR && errno != EAGAIN)) {
      eof_ = true;
    }
  }
}

std::vector<moos::Message> RawClient::read_notifies(std::size_t count, double timeout_s) {
  std::vector<moos::Message> out;
  const double deadline = steady_now_s() + timeout_s;
  while (out.size() < count) {
    const double left_s = deadline - steady_now_s();
    if (left_s <= 0) break;
    const auto packet = read_packet(left_s);
    if (!packet) break;
    for (const auto& m : *packet)
      if (m.type == moos::msg_type::kNotify) out.push_back(m);
  }
  return out;
}

bool RawClient::wait_closed(double timeout_s, std::size_t* discarded_bytes) {
  const double deadline = steady_now_s() + timeout_s;
  std::size_t discarded = 0;
  char buffer[kReadChunkBytes];
  while (!eof_) {
    const double left_s = deadline - steady_now_s();
    if (left_s <= 0) break;
    pollfd pfd{fd_, POLLIN, 0};
    if (::poll(&pfd, 1, static_cast<int>(left_s * 1000) + 1) <= 0) continue;
    const ssize_t n = ::recv(fd_, buffer, sizeof buffer, 0);
    if (n > 0) {
      discarded += static_cast<std::size_t>(n);
    } else if (n == 0 || (errno != EINTR && errno != EAGAIN)) {
      eof_ = true;
    }
  }
  if (discarded_bytes) *discarded_bytes = discarded + reader_.buffered();
  return eof_;
}

void RawClient::close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

void RawClient::shutdown_write() { ::shutdown(fd_, SHUT_WR); }

std::optional<std::vector<moos::Message>> RawClient::exchange(const std::vector<moos::Message>& packet) {
  if (!send(packet)) return std::nullopt;
  return read_packet();
}

}  // namespace moosdb_lite::test
