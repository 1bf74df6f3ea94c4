// A .alog written while a program runs. Contract in include/moos/alog_file.hpp.

#include "moos/alog_file.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <sys/uio.h>
#include <unistd.h>

#include <algorithm>
#include <climits>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstring>
#include <deque>
#include <filesystem>

#include "base/output_file.hpp"
#include "base/text.hpp"
#include "moos/alog.hpp"

namespace moos {

namespace {

/// Lines handed to one writev (Linux's IOV_MAX is 1024).
constexpr int kMaxLinesPerWrite = 256;
constexpr std::string_view kGapPrefix = "%% GAP: ";

double steady_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

/// One queued line: a record, or a gap marker for `lost` records.
struct Entry {
  std::string bytes;       ///< the record; a marker's text once sealed
  std::uint64_t lost = 0;  ///< > 0: a gap marker
  std::string reason;      ///< a marker's REASON
  bool sealed = false;     ///< a marker whose text is fixed (a write has begun to take it)
  bool is_marker() const { return lost > 0; }
};

/// What a queued record holds in memory: its bytes and its place in the queue.
std::size_t held_bytes(const std::string& line) { return line.size() + sizeof(Entry); }

std::string file_name_of(const std::string& path) {
  return std::filesystem::path(path).filename().string();
}

std::string plural(std::uint64_t n, const char* noun) {
  return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

}  // namespace

bool alog_time_is_sane(double message_time_s, double now_s) {
  // A NaN clock (never ours) compares false: the message time is kept.
  return std::isfinite(message_time_s) &&
         !(std::fabs(message_time_s - now_s) > kAlogMaxClockSkew_s);
}

std::string format_alog_gap(std::uint64_t lost, std::string_view reason) {
  std::string out(kGapPrefix);
  out += plural(lost, "record");
  out += " lost (";
  const std::size_t at = out.size();
  out.append(reason);
  std::replace_if(out.begin() + static_cast<std::ptrdiff_t>(at), out.end(),
                  [](char c) { return c == '\n' || c == '\r'; }, ' ');
  out += ")\n";
  return out;
}

std::optional<std::uint64_t> alog_gap_count(std::string_view line) {
  const auto start = line.find_first_not_of(" \t");
  if (start == std::string_view::npos || line.substr(start, kGapPrefix.size()) != kGapPrefix)
    return std::nullopt;
  const std::string_view rest = line.substr(start + kGapPrefix.size());
  std::uint64_t n = 0;
  const auto [end, error] = std::from_chars(rest.data(), rest.data() + rest.size(), n);
  if (error != std::errc() || end == rest.data()) return std::nullopt;
  return n;
}

class AlogFile::Impl {
 public:
  Impl(std::string path, double logstart_s, AlogFileOptions options)
      : path_(std::move(path)), logstart_s_(logstart_s), options_(std::move(options)) {}

  /// Opens the file and writes the header: "" on success, else the problem.
  std::string open_file();
  void add(const Message& msg, double now_s);
  void add_line(std::string line);
  void pump();
  bool close(std::string& problem);

  std::string path_;
  double logstart_s_ = 0.0;
  AlogFileOptions options_;
  std::uint64_t written_ = 0;
  std::uint64_t lost_ = 0;
  std::uint64_t clamped_ = 0;
  std::uint64_t reopened_ = 0;
  std::size_t queued_bytes_ = 0;
  std::string last_problem_;
  bool closed_ = false;

 private:
  void notice(const std::string& text);
  /// Counts `n` records as lost in the gap at the end of the queue.
  void lose(std::uint64_t n, const std::string& reason);
  /// Every queued record is lost: the queue becomes one gap marker.
  void lose_queue(const std::string& reason);
  /// A write failed: the torn line is cut, the queue lost, writing waits for the retry time.
  void fail(const std::string& reason);
  /// Removes the part of the front line a failed write left in the file, or marks it torn.
  void cut_torn_line();
  bool deleted() const;
  /// The file was deleted: create it again (folder, header, a marker for `lost_with_file`).
  void recreate(std::uint64_t lost_with_file);
  void write_queue();
  /// `n` bytes were written from the front of the queue.
  void consume(std::size_t n);
  void seal(Entry& marker) const;
  /// A write took none of the first `count` lines: their markers may still grow.
  void unseal(int count);
  /// Writes what is queued, waiting for a FIFO's reader at most close_wait_s.
  void drain_for_close();

  std::optional<base::OutputFile> file_;
  int fd_ = -1;
  bool regular_ = false;
  std::deque<Entry> queue_;
  std::size_t front_done_ = 0;   ///< bytes of the front line already in the file
  std::uint64_t boundary_ = 0;   ///< bytes of whole lines in the file: where a cut goes
  std::uint64_t in_file_ = 0;    ///< records in the current file
  bool torn_ = false;            ///< the file ends in a fragment: the next line starts anew
  bool waiting_ = false;         ///< after a failure: nothing is written before retry_at_s_
  double retry_at_s_ = 0.0;
  std::string failure_;          ///< the standing problem ("" while writing works)
  bool queue_full_ = false;      ///< dropping for a full queue (noticed once until it drains)
};

std::string AlogFile::Impl::open_file() {
  auto file = base::OutputFile::open(path_, base::OutputMode::kInPlace);
  if (!file) return file.error;
  const std::string header = alog_header(file_name_of(path_), logstart_s_);
  if (auto written = file.value->write(header); !written) return written.error;
  if (auto flushed = file.value->flush(); !flushed) return flushed.error;
  fd_ = file.value->descriptor();
  regular_ = !file.value->written_through();
  ::fcntl(fd_, F_SETFL, ::fcntl(fd_, F_GETFL) | O_NONBLOCK);  // never wait for a reader
  file_ = std::move(file.value);
  boundary_ = header.size();
  in_file_ = 0;
  torn_ = false;
  front_done_ = 0;
  return "";
}

void AlogFile::Impl::notice(const std::string& text) {
  if (options_.notice) options_.notice("'" + path_ + "': " + text);
}

void AlogFile::Impl::add(const Message& msg, double now_s) {
  double time_s = msg.time;
  if (!alog_time_is_sane(time_s, now_s)) {
    if (clamped_++ == 0) {
      notice("message time " + base::format_g(time_s) + " of " + base::log_excerpt(msg.key) +
             " is not finite or beyond what a log reader places: such times are " +
             "logged at this program's clock (and counted)");
    }
    time_s = now_s;
  }
  // format_alog_line(alog_entry(...)) without copying the columns (a server logs every NOTIFY).
  const bool text = msg.data_type != data_type::kDouble && msg.data_type != data_type::kBinary &&
                    msg.data_type != data_type::kNotSet;  // alog_value is the string itself
  std::string line;
  line.reserve(48 + msg.key.size() + msg.source.size() + (text ? msg.sval.size() : 32));
  append_alog_columns(line, time_s - logstart_s_, msg.key, msg.source);
  if (text) {
    append_alog_value(line, msg.sval);
  } else {
    append_alog_value(line, alog_value(msg));
  }
  add_line(std::move(line));
}

void AlogFile::Impl::add_line(std::string line) {
  if (closed_) return;
  if (!file_ || waiting_) return lose(1, failure_);
  if (queued_bytes_ > 0 && queued_bytes_ + held_bytes(line) > options_.max_queued_bytes) {
    if (!queue_full_) {
      queue_full_ = true;
      notice("the file takes records more slowly than they come: with " +
             std::to_string(queued_bytes_) + " bytes queued, records are dropped and counted");
    }
    return lose(1, "the queue was full: the file took records more slowly than they came");
  }
  queued_bytes_ += held_bytes(line);
  queue_.push_back(Entry{std::move(line), 0, std::string(), false});
}

void AlogFile::Impl::lose(std::uint64_t n, const std::string& reason) {
  if (n == 0) return;
  lost_ += n;
  if (!queue_.empty() && queue_.back().is_marker() && !queue_.back().sealed) {
    queue_.back().lost += n;
  } else {
    queue_.push_back(Entry{std::string(), n, reason, false});
  }
}

void AlogFile::Impl::lose_queue(const std::string& reason) {
  cut_torn_line();
  std::uint64_t records = 0;
  std::uint64_t gaps = 0;
  for (const Entry& e : queue_) (e.is_marker() ? gaps += e.lost : ++records);
  lost_ += records;
  queue_.clear();
  queued_bytes_ = 0;
  front_done_ = 0;
  if (records + gaps > 0) queue_.push_back(Entry{std::string(), records + gaps, reason, false});
}

void AlogFile::Impl::fail(const std::string& reason) {
  last_problem_ = reason;
  lose_queue(reason);
  waiting_ = true;
  retry_at_s_ = steady_s() + options_.retry_interval_s;
  if (failure_ != reason) {
    failure_ = reason;
    notice(reason + "; records are lost and counted until writing works again");
  }
}

void AlogFile::Impl::cut_torn_line() {
  if (front_done_ == 0 || !file_) return;
  const auto at = static_cast<off_t>(boundary_);
  if (regular_ && ::ftruncate(fd_, at) == 0 && ::lseek(fd_, at, SEEK_SET) == at) return;
  torn_ = true;
}

bool AlogFile::Impl::deleted() const {
  struct stat info {};
  return regular_ && ::fstat(fd_, &info) == 0 && info.st_nlink == 0;
}

void AlogFile::Impl::recreate(std::uint64_t lost_with_file) {
  file_.reset();  // (closes the deleted file)
  fd_ = -1;
  std::error_code ignored;
  const auto folder = std::filesystem::path(path_).parent_path();
  if (!folder.empty()) std::filesystem::create_directories(folder, ignored);
  const std::string problem = open_file();
  const std::string why = "the log file was deleted while it was written";
  if (!problem.empty()) {
    lose(lost_with_file, why);
    return fail(why + " and cannot be created again: " + problem);
  }
  ++reopened_;
  if (lost_with_file > 0) {
    lost_ += lost_with_file;
    queue_.push_front(Entry{std::string(), lost_with_file, why + "; created again", false});
  }
  failure_.clear();
  waiting_ = false;
  notice(why + ": created again, with its header and a gap marker (" +
         plural(lost_with_file, "record") + " went with the deleted file)");
}

void AlogFile::Impl::pump() {
  if (closed_) return;
  if (waiting_) {
    if (steady_s() < retry_at_s_) return;
    waiting_ = false;
  }
  if (!file_) {
    recreate(0);
    if (!file_) return;
  }
  if (queue_.empty()) return;
  if (deleted()) {
    recreate(in_file_);
    if (!file_) return;
  }
  write_queue();
}

void AlogFile::Impl::seal(Entry& marker) const {
  marker.bytes = (torn_ ? "\n" : "") + format_alog_gap(marker.lost, marker.reason);
  marker.sealed = true;
}

void AlogFile::Impl::unseal(int count) {
  for (int i = front_done_ > 0 ? 1 : 0; i < count; ++i)
    queue_[static_cast<std::size_t>(i)].sealed = false;
}

void AlogFile::Impl::write_queue() {
  while (!queue_.empty()) {
    iovec parts[kMaxLinesPerWrite];
    int count = 0;
    std::size_t bytes = 0;
    for (auto it = queue_.begin(); it != queue_.end() && count < kMaxLinesPerWrite; ++it) {
      const bool was_sealed = it->sealed;
      if (it->is_marker() && !was_sealed) seal(*it);
      const std::size_t skip = count == 0 ? front_done_ : 0;
      const std::size_t size = it->bytes.size() - skip;
      // A pipe takes up to PIPE_BUF bytes whole or not at all: a FIFO whose reader stalls
      // then holds whole lines (a longer line goes alone, in parts).
      if (!regular_ && count > 0 && bytes + size > PIPE_BUF) {
        it->sealed = was_sealed;
        break;
      }
      parts[count++] = iovec{it->bytes.data() + skip, size};
      bytes += size;
    }
    const ssize_t n = ::writev(fd_, parts, count);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) return unseal(count);
    if (n <= 0) return fail(std::string("write failed: ") + std::strerror(n < 0 ? errno : EIO));
    consume(static_cast<std::size_t>(n));
  }
  queue_full_ = false;
}

void AlogFile::Impl::consume(std::size_t n) {
  while (n > 0 && !queue_.empty()) {
    Entry& e = queue_.front();
    const std::size_t rest = e.bytes.size() - front_done_;
    if (n < rest) {
      front_done_ += n;
      return;
    }
    n -= rest;
    boundary_ += e.bytes.size();
    if (e.is_marker()) {
      if (!failure_.empty()) notice("writing again; a gap marker counts the records lost");
      failure_.clear();
    } else {
      ++written_;
      ++in_file_;
      queued_bytes_ -= held_bytes(e.bytes);
    }
    torn_ = false;
    front_done_ = 0;
    queue_.pop_front();
  }
}

void AlogFile::Impl::drain_for_close() {
  waiting_ = false;  // one more attempt, now
  const double give_up = steady_s() + options_.close_wait_s;
  while (true) {
    pump();
    if (queue_.empty() || waiting_ || !file_) return;
    const double left_s = give_up - steady_s();
    if (left_s <= 0.0) return;
    pollfd ready{fd_, POLLOUT, 0};
    ::poll(&ready, 1, std::max(1, static_cast<int>(left_s * 1000.0)));
  }
}

bool AlogFile::Impl::close(std::string& problem) {
  if (closed_) {
    problem = last_problem_;
    return last_problem_.empty() && lost_ == 0;
  }
  drain_for_close();
  const bool stalled =
      std::any_of(queue_.begin(), queue_.end(), [](const Entry& e) { return !e.is_marker(); });
  if (stalled && file_ && !waiting_) {
    const std::string why = "not taken before the program ended";
    last_problem_ = "records were " + why;
    lose_queue(why);
    write_queue();  // the closing marker, if the file takes it now
  }
  lose_queue(last_problem_);  // (counts what is still queued)
  queue_.clear();
  closed_ = true;
  if (file_) {
    if (auto closing = file_->commit(); !closing) last_problem_ = closing.error;
    file_.reset();
  }
  fd_ = -1;
  if (lost_ > 0) {
    problem = plural(lost_, "record") + " lost" +
              (last_problem_.empty() ? std::string() : " (last problem: " + last_problem_ + ")");
  } else {
    problem = last_problem_;
  }
  return problem.empty();
}

// ---- AlogFile ----------------------------------------------------------------------------------

AlogFile::AlogFile(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
AlogFile::AlogFile(AlogFile&&) noexcept = default;
AlogFile& AlogFile::operator=(AlogFile&& other) noexcept {
  if (this != &other) {
    if (impl_) {
      std::string ignored;
      impl_->close(ignored);
    }
    impl_ = std::move(other.impl_);
  }
  return *this;
}

AlogFile::~AlogFile() {
  if (!impl_) return;
  std::string ignored;
  impl_->close(ignored);
}

std::optional<AlogFile> AlogFile::open(const std::string& path, double logstart_s,
                                       AlogFileOptions options, std::string& problem) {
  auto impl = std::make_unique<Impl>(path, logstart_s, std::move(options));
  problem = impl->open_file();
  if (!problem.empty()) return std::nullopt;
  return AlogFile(std::move(impl));
}

void AlogFile::add(const Message& msg, double now_s) { impl_->add(msg, now_s); }
void AlogFile::add_line(std::string line) { impl_->add_line(std::move(line)); }
void AlogFile::pump() { impl_->pump(); }
bool AlogFile::close(std::string& problem) { return impl_->close(problem); }
const std::string& AlogFile::path() const { return impl_->path_; }
std::uint64_t AlogFile::records_written() const { return impl_->written_; }
std::uint64_t AlogFile::records_lost() const { return impl_->lost_; }
std::uint64_t AlogFile::times_clamped() const { return impl_->clamped_; }
std::uint64_t AlogFile::reopened() const { return impl_->reopened_; }
std::size_t AlogFile::queued_bytes() const { return impl_->queued_bytes_; }
const std::string& AlogFile::last_problem() const { return impl_->last_problem_; }

}  // namespace moos
