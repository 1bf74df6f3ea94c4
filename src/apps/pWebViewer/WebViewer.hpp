#pragma once
// WebViewer: the pWebViewer MOOS application (docs/viewer.md). It subscribes to the
// watched variables, keeps the retained state and serves the page over HTTP with server-sent
// events from threads of its own.
//
// Contract
// - Configuration: viewer_config.hpp. A bad line is a configuration warning; an address that
//   cannot be bound ends start-up (exit 1) with a message naming it.
// - At start-up the server listens and the URL is printed on standard output as
//   `pWebViewer: serving http://HOST:PORT/?token=TOKEN` (the port the OS chose when
//   http_port = 0; the token the page needs to press buttons, request_guard.hpp). The AppCast
//   shows the URL without the token, since every MOOS client can read it.
// - Mail of watched variables goes to the LiveFeed in the order the app base hands it over
//   (sorted by time within a cycle). The MOOS side never waits for a browser (event_hub.hpp).
// - Each iteration: the button presses the server took since the last one are posted (each
//   assignment in order, on this thread); a clock event goes out once per real second; with
//   appcast_request, APPCAST_REQ (node=all, app=all, 30 MOOS s) every 20 MOOS s, so every app
//   keeps posting its AppCast. On (re)connection: PMV_CONNECT, which makes uFldHazardSensor post
//   its markers again (as for pMarineViewer), and the first APPCAST_REQ.

#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "http_server.hpp"
#include "live_feed.hpp"
#include "mission_app.hpp"
#include "viewer_config.hpp"

namespace web_viewer {

inline constexpr const char* kAppName = "pWebViewer";
inline constexpr double kDefaultAppTick_hz = 4.0;
/// APPCAST_REQ: its lifetime and how often it is renewed (MOOS seconds).
inline constexpr double kAppCastRequestDuration_s = 30.0;
inline constexpr double kAppCastRequestPeriod_s = 20.0;

moos::AppTraits viewer_traits();
/// The APPCAST_REQ text pWebViewer posts.
std::string appcast_request_text();
/// The mission's LatOrigin/LongOrigin (both or neither) into the hello.
void set_datum(const moos::AppSettings& settings, Hello& hello);

class WebViewer final : public mission_app::MissionApp {
 public:
  WebViewer();
  ~WebViewer() override;

  const ViewerConfig& config() const { return config_; }
  /// The port the server listens on (0 before start-up).
  int http_port() const { return server_ ? server_->port() : 0; }
  std::string url() const;
  /// url() with the run's token: what the user opens to press buttons.
  std::string page_url() const;
  /// The run's token ("" before start-up).
  std::string token() const { return server_ ? server_->token() : std::string(); }
  /// Presses button `index` as POST /button/<index> does; false when it is not configured.
  bool press(int index);
  const LiveFeed* feed() const { return feed_.get(); }

 protected:
  bool on_start_up() override;
  void on_connect_to_server() override;
  void on_new_mail(const std::vector<moos::Message>& mail) override;
  void on_iterate() override;
  std::string build_report() override;

 private:
  /// The hello's fixed part, from the settings (this thread); hello() adds the time (any thread).
  void update_hello();
  std::string hello() const;
  void post_button(int index);

  ViewerConfig config_;
  std::unique_ptr<LiveFeed> feed_;
  std::unique_ptr<HttpServer> server_;
  std::atomic<double> now_s_{0.0};  // MOOS time of the latest cycle, for the hello
  mutable std::mutex hello_mutex_;
  Hello hello_;
  std::mutex presses_mutex_;
  std::vector<int> presses_;        // buttons pressed since the last iteration
  std::uint64_t presses_posted_ = 0;
  std::uint64_t mail_seen_ = 0;
  std::optional<double> last_clock_s_;
  std::optional<double> last_request_s_;
};

}  // namespace web_viewer
