#include "live_feed.hpp"

namespace web_viewer {

LiveFeed::LiveFeed(const FeedLimits& limits, std::function<std::string()> hello)
    : hello_(std::move(hello)),
      state_(limits.retention),
      hub_(limits.max_clients, limits.max_queued, [this] { return first_events(); }) {}

std::vector<std::string> LiveFeed::first_events() {
  std::vector<std::string> out;
  const std::vector<Mail> kept = state_.snapshot();
  out.reserve(kept.size() + 1);
  out.push_back(hello_());
  for (const Mail& m : kept) out.push_back(mail_json(m));
  return out;
}

void LiveFeed::on_mail(const Mail& mail) {
  hub_.publish(mail_json(mail), [&] {
    state_.apply(mail);
    retained_ = state_.size();
    refused_ = state_.refused();
  });
}

void LiveFeed::on_clock(double time_s, double warp) {
  hub_.publish(clock_json(time_s, warp), [&] { state_.set_clock(time_s); });
}

std::size_t LiveFeed::retained() const { return retained_; }
std::uint64_t LiveFeed::refused() const { return refused_; }

}  // namespace web_viewer
