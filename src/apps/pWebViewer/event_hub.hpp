#pragma once
// The fan-out from the MOOS side to the browsers: each connected page has its own bounded queue
// of event texts (JSON, one per server-sent event).
//
// Contract
// - publish() never blocks on a browser: it appends to every queue under one short lock. A
//   queue that would hold more than `max_queued` live events marks its client as fallen behind:
//   the client is dropped (its stream ends; the browser's EventSource reconnects and gets a fresh
//   snapshot) and counted in dropped().
// - unsubscribe(client, true): a client whose stream the server ended because it took nothing
//   for the write timeout; it is counted in dropped() too (unless publish() dropped it first).
// - subscribe() registers a client with its first events (from `first_events`: the hello and the
//   retained state, which are not counted against max_queued); nullptr when `max_clients` are
//   connected already. `first_events` runs under the hub's lock, as publish()'s update does, so
//   a client misses no event and gets none twice.
// - ClientQueue::take() waits up to a timeout for events and hands over all that are queued;
//   nullopt once the client was dropped or the hub closed.

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace web_viewer {

class ClientQueue {
 public:
  std::optional<std::vector<std::string>> take(double timeout_s);

 private:
  friend class EventHub;
  std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<std::string> events_;
  std::size_t first_events_ = 0;  // initial events still queued (not counted against the bound)
  bool ended_ = false;
};

class EventHub {
 public:
  using FirstEvents = std::function<std::vector<std::string>()>;
  EventHub(std::size_t max_clients, std::size_t max_queued, FirstEvents first_events)
      : max_clients_(max_clients), max_queued_(max_queued), first_events_(std::move(first_events)) {}

  std::shared_ptr<ClientQueue> subscribe();
  void unsubscribe(const std::shared_ptr<ClientQueue>& client, bool fell_behind = false);
  /// Runs `update` and then queues `event` for every client, under the hub's lock.
  void publish(const std::string& event, const std::function<void()>& update = {});
  /// Ends every client's stream (at shut-down).
  void close_all();

  std::size_t clients() const;
  std::uint64_t dropped() const;
  std::uint64_t served() const;

 private:
  static void end(ClientQueue& client);
  mutable std::mutex mutex_;
  const std::size_t max_clients_;
  const std::size_t max_queued_;
  const FirstEvents first_events_;
  std::vector<std::shared_ptr<ClientQueue>> clients_;
  std::uint64_t dropped_ = 0;
  std::uint64_t served_ = 0;
};

}  // namespace web_viewer
