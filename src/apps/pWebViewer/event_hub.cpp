#include "event_hub.hpp"

#include <algorithm>
#include <chrono>

namespace web_viewer {

std::optional<std::vector<std::string>> ClientQueue::take(double timeout_s) {
  std::unique_lock<std::mutex> lock(mutex_);
  ready_.wait_for(lock, std::chrono::duration<double>(timeout_s),
                  [&] { return ended_ || !events_.empty(); });
  if (ended_) return std::nullopt;
  std::vector<std::string> out(std::make_move_iterator(events_.begin()),
                               std::make_move_iterator(events_.end()));
  events_.clear();
  first_events_ = 0;
  return out;
}

void EventHub::end(ClientQueue& client) {
  {
    std::lock_guard<std::mutex> lock(client.mutex_);
    client.ended_ = true;
    client.events_.clear();
  }
  client.ready_.notify_all();
}

std::shared_ptr<ClientQueue> EventHub::subscribe() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (clients_.size() >= max_clients_) return nullptr;
  auto client = std::make_shared<ClientQueue>();
  std::vector<std::string> first = first_events_ ? first_events_() : std::vector<std::string>();
  client->first_events_ = first.size();
  client->events_.assign(std::make_move_iterator(first.begin()), std::make_move_iterator(first.end()));
  clients_.push_back(client);
  ++served_;
  return client;
}

void EventHub::unsubscribe(const std::shared_ptr<ClientQueue>& client, bool fell_behind) {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto it = std::find(clients_.begin(), clients_.end(), client);
  if (it == clients_.end()) return;
  clients_.erase(it);
  if (fell_behind) ++dropped_;
}

void EventHub::publish(const std::string& event, const std::function<void()>& update) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (update) update();
  for (auto it = clients_.begin(); it != clients_.end();) {
    ClientQueue& client = **it;
    bool fell_behind = false;
    {
      std::lock_guard<std::mutex> client_lock(client.mutex_);
      fell_behind = client.events_.size() - client.first_events_ >= max_queued_;
      if (!fell_behind) client.events_.push_back(event);
    }
    if (fell_behind) {
      end(client);
      ++dropped_;
      it = clients_.erase(it);
      continue;
    }
    client.ready_.notify_one();
    ++it;
  }
}

void EventHub::close_all() {
  std::lock_guard<std::mutex> lock(mutex_);
  for (const auto& client : clients_) end(*client);
  clients_.clear();
}

std::size_t EventHub::clients() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return clients_.size();
}

std::uint64_t EventHub::dropped() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return dropped_;
}

std::uint64_t EventHub::served() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return served_;
}

}  // namespace web_viewer
