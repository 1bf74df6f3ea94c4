#pragma once
// The httplib::Stream through which BoundedHttpServer serves one connection: it
// gives httplib at most a bounded number of bytes per request, so that nothing a client sends
// can make httplib keep more.
//
// Contract
// - begin_request() starts a request: from then read() gives at most `head_limit` bytes; after
//   end_head() (the head was parsed) at most `body_limit` more. At the bound read() returns 0,
//   as at the end of the stream, so that httplib still answers (400, 414 or 413) instead of
//   dropping the connection silently; exhausted() then says the connection must close, since
//   the rest of the request was never read.
// - A request must arrive whole within `request_deadline_ms` of begin_request() (called once its
//   first byte is there), however slowly it trickles: past the deadline read() returns 0 and
//   exhausted() is true, as at a bound. Writes have no such deadline (the event stream is one
//   long response).
// - read() waits at most `read_timeout_ms` for data (-1 on timeout or error), write() at most
//   `write_timeout_ms` for room (-1); a write may be partial, as httplib expects of send().
// - The stream does not own the socket.

#include <httplib.h>

#include <array>
#include <chrono>
#include <cstddef>
#include <string>

namespace web_viewer {

class BoundedStream final : public httplib::Stream {
 public:
  BoundedStream(socket_t sock, int read_timeout_ms, int write_timeout_ms, std::size_t head_limit,
                std::size_t body_limit, int request_deadline_ms);

  void begin_request();
  void end_head();
  bool exhausted() const { return exhausted_; }
  /// Bytes of the current request's body given to httplib so far.
  std::size_t body_given() const { return in_head_ ? 0 : given_; }
  /// Bytes received and not yet given to httplib (a pipelined request).
  bool has_buffered() const { return begin_ < end_; }
  /// Whether data arrives within `timeout_ms` (or is buffered).
  bool wait_readable(int timeout_ms) const;

  bool is_readable() const override;
  bool is_writable() const override;
  ssize_t read(char* ptr, size_t size) override;
  ssize_t write(const char* ptr, size_t size) override;
  void get_remote_ip_and_port(std::string& ip, int& port) const override;
  void get_local_ip_and_port(std::string& ip, int& port) const override;
  socket_t socket() const override { return sock_; }

 private:
  /// Receives into the empty buffer: the count, 0 at the end, -1 on timeout or error.
  ssize_t fill(int timeout_ms);
  /// Milliseconds left before the request's deadline (0 when it has passed).
  int until_deadline_ms() const;

  socket_t sock_;
  int read_timeout_ms_;
  int write_timeout_ms_;
  std::size_t head_limit_;
  std::size_t body_limit_;
  int request_deadline_ms_;
  std::chrono::steady_clock::time_point deadline_{};
  bool in_head_ = true;
  std::size_t given_ = 0;  // bytes given to httplib in this part of the request
  bool exhausted_ = false;
  // httplib reads a request head one byte at a time: receive in blocks, as its own stream does.
  std::array<char, 4096> buffer_{};
  std::size_t begin_ = 0;
  std::size_t end_ = 0;
};

}  // namespace web_viewer
