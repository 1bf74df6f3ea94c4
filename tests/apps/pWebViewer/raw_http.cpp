#include "raw_http.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstdint>

#include "base/text.hpp"
#include "child_process.hpp"

namespace web_viewer::raw_http {

int connect_to(int port, const char* source) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  if (source) {
    sockaddr_in local{};
    local.sin_family = AF_INET;
    if (::inet_pton(AF_INET, source, &local.sin_addr) != 1 ||
        ::bind(fd, reinterpret_cast<sockaddr*>(&local), sizeof local) != 0) {
      ::close(fd);
      return -1;
    }
  }
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0) return fd;
  ::close(fd);
  return -1;
}

std::string read_reply(int fd, double timeout_s) {
  timeval tick{0, 100000};
  ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &tick, sizeof tick);
  const double end = test_support::steady_now_s() + timeout_s;
  std::string reply;
  char buffer[4096];
  while (test_support::steady_now_s() < end) {
    const ssize_t n = ::recv(fd, buffer, sizeof buffer, 0);
    if (n == 0 || (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)) break;
    if (n > 0) reply.append(buffer, static_cast<std::size_t>(n));
  }
  return reply;
}

std::string raw_exchange(int port, const std::string& request, double timeout_s, const char* source) {
  const int fd = connect_to(port, source);
  if (fd < 0) return "";
  std::string reply;
  if (::send(fd, request.data(), request.size(), MSG_NOSIGNAL) >= 0)
    reply = read_reply(fd, timeout_s);
  ::close(fd);
  return reply;
}

int status_of(const std::string& reply) {
  if (reply.size() < 12 || reply.compare(0, 5, "HTTP/") != 0) return 0;
  return std::stoi(reply.substr(9, 3));
}

std::string body_of(const std::string& reply) {
  const auto end = reply.find("\r\n\r\n");
  return end == std::string::npos ? std::string() : reply.substr(end + 4);
}

std::string header_of(const std::string& reply, const std::string& name) {
  const std::string head = reply.substr(0, reply.find("\r\n\r\n"));
  for (const auto line : base::split(head, '\n')) {
    const auto colon = line.find(':');
    if (colon != std::string_view::npos && base::iequals(line.substr(0, colon), name))
      return std::string(base::trim(line.substr(colon + 1)));
  }
  return "";
}

std::string dechunked(const std::string& body) {
  std::string out;
  std::size_t at = 0;
  while (true) {
    const auto line_end = body.find("\r\n", at);
    if (line_end == std::string::npos) break;
    const std::string size_line = body.substr(at, line_end - at);
    char* end = nullptr;
    const unsigned long size = std::strtoul(size_line.c_str(), &end, 16);
    if (size_line.empty() || *end != '\0' || size == 0 || line_end + 2 + size + 2 > body.size()) break;
    out += body.substr(line_end + 2, size);
    at = line_end + 2 + size + 2;
  }
  return out;
}

Reply request(int port, const std::string& method, const std::string& target, const std::string& headers,
              double timeout_s) {
  const std::string text = raw_exchange(port, method + " " + target + " HTTP/1.1\r\nHost: 127.0.0.1:" +
                                                  std::to_string(port) + "\r\n" + headers +
                                                  "Content-Length: 0\r\nConnection: close\r\n\r\n",
                                        timeout_s);
  Reply reply;
  reply.status = status_of(text);
  reply.head = text.substr(0, text.find("\r\n\r\n"));
  reply.body = body_of(text);
  if (base::iequals(reply.header("Transfer-Encoding"), "chunked")) reply.body = dechunked(reply.body);
  return reply;
}

EventStream::EventStream(int port) : fd_(connect_to(port)) {
  const std::string get = "GET /events HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) + "\r\n\r\n";
  if (fd_ >= 0) ::send(fd_, get.data(), get.size(), MSG_NOSIGNAL);
}

EventStream::~EventStream() {
  if (fd_ >= 0) ::close(fd_);
}

bool EventStream::read(double wait_s) {
  if (fd_ < 0) return false;
  timeval tick{0, 50000};
  ::setsockopt(fd_, SOL_SOCKET, SO_RCVTIMEO, &tick, sizeof tick);
  const double end = test_support::steady_now_s() + wait_s;
  char buffer[4096];
  while (test_support::steady_now_s() < end) {
    const ssize_t n = ::recv(fd_, buffer, sizeof buffer, 0);
    if (n == 0 || (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)) return false;
    if (n > 0) raw_.append(buffer, static_cast<std::size_t>(n));
  }
  return true;
}

std::string read_events(int port, const std::string& until, double timeout_s) {
  EventStream stream(port);
  const double end = test_support::steady_now_s() + timeout_s;
  while (stream.text().find(until) == std::string::npos && test_support::steady_now_s() < end &&
         stream.read(0.1)) {
  }
  return stream.text();
}

}  // namespace web_viewer::raw_http
