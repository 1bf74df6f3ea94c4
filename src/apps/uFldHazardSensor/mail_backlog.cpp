// The sensor's mail backlog. Contract in mail_backlog.hpp.

#include "mail_backlog.hpp"

#include <algorithm>
#include <map>
#include <string>
#include <utility>

namespace ufld_hazard_sensor {

MailBacklog::MailBacklog(std::size_t per_iteration, std::size_t max_messages,
                         std::size_t max_bytes)
    : per_iteration_(std::max<std::size_t>(per_iteration, 1)),
      max_messages_(std::max<std::size_t>(max_messages, 1)),
      max_bytes_(max_bytes) {}

std::size_t MailBacklog::add(std::vector<moos::Message> mail) {
  for (moos::Message& m : mail) {
    bytes_ += m.encoded_size();
    mail_.push_back(std::move(m));
  }
  return enforce_bounds();
}

std::size_t MailBacklog::enforce_bounds() {
  std::size_t dropped = 0;
  while (mail_.size() > max_messages_ || (bytes_ > max_bytes_ && mail_.size() > 1)) {
    // The busiest source by bytes when bytes overflow, else by messages.
    const bool by_bytes = bytes_ > max_bytes_;
    std::map<std::string, std::size_t> held;
    for (const moos::Message& m : mail_) held[m.source] += by_bytes ? m.encoded_size() : 1;
    const auto busiest = std::max_element(
        held.begin(), held.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
    const std::string source = busiest->first;
    // One pass: the busiest source's oldest messages go until the bounds hold.
    std::deque<moos::Message> kept;
    std::size_t removed = 0;
    for (moos::Message& m : mail_) {
      const bool over = mail_.size() - removed > max_messages_ || bytes_ > max_bytes_;
      if (over && m.source == source) {
        bytes_ -= m.encoded_size();
        ++removed;
      } else {
        kept.push_back(std::move(m));
      }
    }
    mail_.swap(kept);
    dropped += removed;
  }
  return dropped;
}

std::size_t MailBacklog::share_per_source() const {
  std::map<std::string, std::size_t> counts;
  for (const moos::Message& m : mail_) ++counts[m.source];
  // The largest share s with sum(min(count, s)) <= per_iteration (water filling).
  std::vector<std::size_t> sizes;
  for (const auto& entry : counts) sizes.push_back(entry.second);
  std::sort(sizes.begin(), sizes.end());
  std::size_t budget = per_iteration_;
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    const std::size_t sources_left = sizes.size() - i;
    if (sizes[i] * sources_left > budget) return std::max<std::size_t>(budget / sources_left, 1);
    budget -= sizes[i];
  }
  return per_iteration_;
}

std::vector<moos::Message> MailBacklog::take() {
  std::vector<moos::Message> out;
  if (mail_.size() <= per_iteration_) {
    out.assign(std::make_move_iterator(mail_.begin()), std::make_move_iterator(mail_.end()));
    mail_.clear();
    bytes_ = 0;
    return out;
  }
  const std::size_t share = share_per_source();
  std::map<std::string, std::size_t> taken;
  std::deque<moos::Message> kept;
  for (moos::Message& m : mail_) {
    std::size_t& count = taken[m.source];
    if (count < share && out.size() < per_iteration_) {
      ++count;
      bytes_ -= m.encoded_size();
      out.push_back(std::move(m));
    } else {
      kept.push_back(std::move(m));
    }
  }
  mail_.swap(kept);
  return out;
}

}  // namespace ufld_hazard_sensor
