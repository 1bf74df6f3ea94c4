// The sensor's mail backlog. Contract in mail_backlog.hpp.

#include "mail_backlog.hpp"

#include <algorithm>
#include <iterator>
#include <utility>

namespace ufld_hazard_sensor {

MailBacklog::MailBacklog(std::size_t per_iteration, std::size_t max_messages,
                         std::size_t max_bytes)
    : per_iteration_(std::max<std::size_t>(per_iteration, 1)),
      max_messages_(std::max<std::size_t>(max_messages, 1)),
      max_bytes_(max_bytes) {}

std::size_t MailBacklog::add(std::vector<moos::Message> mail) {
  for (moos::Message& m : mail) {
    const std::size_t size = m.encoded_size();
    bytes_ += size;
    Held& held = held_[m.source];
    ++held.messages;
    held.bytes += size;
    mail_.push_back(std::move(m));
  }
  return enforce_bounds();
}

void MailBacklog::forget(const moos::Message& m) {
  const std::size_t size = m.encoded_size();
  bytes_ -= size;
  const auto it = held_.find(m.source);
  if (--it->second.messages == 0) {
    held_.erase(it);
  } else {
    it->second.bytes -= size;
  }
}

template <typename Pick, typename Leave, typename Done>
void MailBacklog::remove_in_order(Pick pick, Leave leave, Done done) {
  // The scanned part is rebuilt (kept messages in order), the rest is not touched.
  std::vector<moos::Message> kept;
  std::size_t scanned = 0;
  for (auto it = mail_.begin(); it != mail_.end() && !done(); ++it, ++scanned) {
    if (pick(*it)) {
      forget(*it);
      leave(std::move(*it));
    } else {
      kept.push_back(std::move(*it));
    }
  }
  mail_.erase(mail_.begin(), mail_.begin() + static_cast<std::ptrdiff_t>(scanned));
  mail_.insert(mail_.begin(), std::make_move_iterator(kept.begin()), std::make_move_iterator(kept.end()));
}

std::string MailBacklog::busiest_source(bool by_bytes) const {
  const std::string* best = nullptr;
  std::size_t most = 0;
  for (const auto& [source, held] : held_) {
    const std::size_t amount = by_bytes ? held.bytes : held.messages;
    if (best == nullptr || amount > most || (amount == most && source < *best)) {
      best = &source;
      most = amount;
    }
  }
  return best ? *best : std::string();
}

std::size_t MailBacklog::enforce_bounds() {
  std::size_t dropped = 0;
  while (over_bounds()) {
    // The busiest source by bytes when bytes overflow, else by messages; its oldest messages
    // go until the bounds hold.
    const std::string source = busiest_source(bytes_ > max_bytes_);
    std::size_t removed = 0;
    remove_in_order([&](const moos::Message& m) { return m.source == source; },
                    [&](moos::Message&&) { ++removed; },
                    [&] { return !(mail_.size() - removed > max_messages_ || bytes_ > max_bytes_); });
    dropped += removed;
  }
  return dropped;
}

std::size_t MailBacklog::share_per_source() const {
  // The largest share s with sum(min(count, s)) <= per_iteration (water filling).
  std::vector<std::size_t> sizes;
  sizes.reserve(held_.size());
  for (const auto& entry : held_) sizes.push_back(entry.second.messages);
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
    held_.clear();
    bytes_ = 0;
    return out;
  }
  const std::size_t share = share_per_source();
  out.reserve(per_iteration_);
  std::unordered_map<std::string, std::size_t> taken;
  remove_in_order(
      [&](const moos::Message& m) {
        std::size_t& count = taken[m.source];
        if (count >= share) return false;
        ++count;
        return true;
      },
      [&](moos::Message&& m) { out.push_back(std::move(m)); },
      [&] { return out.size() >= per_iteration_; });
  return out;
}

}  // namespace ufld_hazard_sensor
