#include "WebViewer.hpp"

#include <iostream>

#include "base/text.hpp"
#include "replay_log.hpp"

namespace web_viewer {

moos::AppTraits viewer_traits() { return mission_app::mission_traits(kAppName, kDefaultAppTick_hz); }

std::string appcast_request_text() {
  return "node=all,app=all,duration=" + base::fmt(kAppCastRequestDuration_s, 1) + ",key=" + kAppName +
         ",thresh=any";
}

void set_datum(const moos::AppSettings& settings, Hello& hello) {
  const auto lat = settings.global_double("LatOrigin");
  const auto lon = settings.global_double("LongOrigin");
  if (lat && lon) {
    hello.lat_origin_deg = lat;
    hello.lon_origin_deg = lon;
  }
}

WebViewer::WebViewer() : mission_app::MissionApp(viewer_traits()) {}

WebViewer::~WebViewer() {
  if (server_) server_->stop();
}

std::string WebViewer::url() const {
  return server_url(config_.http.bind_address, http_port());
}

std::string WebViewer::page_url() const {
  return server_ ? url() + "?token=" + server_->token() : url();
}

void WebViewer::update_hello() {
  Hello h = configured_hello(config_);
  h.community = community();
  h.warp = comms().time_warp();
  set_datum(settings(), h);
  std::lock_guard<std::mutex> lock(hello_mutex_);
  hello_ = std::move(h);
}

std::string WebViewer::hello() const {
  std::lock_guard<std::mutex> lock(hello_mutex_);
  Hello h = hello_;
  h.time_s = now_s_;
  return hello_json(h);
}

bool WebViewer::press(int index) {
  for (const Button& b : config_.buttons)
    if (b.index == index) {
      std::lock_guard<std::mutex> lock(presses_mutex_);
      presses_.push_back(index);
      return true;
    }
  return false;
}

bool WebViewer::on_start_up() {
  std::vector<std::string> warnings;
  config_ = read_viewer_config(config_lines(), &warnings);
  for (const std::string& w : warnings) report_config_warning(w);
  now_s_ = moos_time();
  update_hello();
  feed_ = std::make_unique<LiveFeed>(config_.limits, [this] { return hello(); });
  server_ = std::make_unique<HttpServer>(feed_->hub(), [this](int n) { return press(n); });
  std::string error;
  if (!server_->start(config_.http, &error)) {
    report_config_warning(error);
    std::cerr << kAppName << ": " << error << std::endl;
    return false;
  }
  std::cout << kAppName << ": serving " << page_url() << std::endl;
  for (const std::string& w : config_.watch) {
    if (w.find_first_of("*?") != std::string::npos)
      register_wildcard(w, "*");
    else
      register_variable(w);
  }
  return true;
}

void WebViewer::on_connect_to_server() {
  update_hello();  // the community may come from the server
  notify("PMV_CONNECT", kAppName);
  last_request_s_.reset();  // ask for the AppCasts again at once
}

void WebViewer::on_new_mail(const std::vector<moos::Message>& mail) {
  for (const moos::Message& m : mail) {
    if (!watch_matches(config_.watch, m.key)) continue;
    if (const auto viewable = from_message(m)) {
      ++mail_seen_;
      feed_->on_mail(*viewable);
    }
  }
}

void WebViewer::post_button(int index) {
  for (const Button& b : config_.buttons) {
    if (b.index != index) continue;
    for (const Assignment& a : b.assignments) {
      if (a.is_double)
        notify(a.var, a.dval);
      else
        notify(a.var, a.sval);
    }
    ++presses_posted_;
    report_event("button " + std::to_string(index) + " (" + b.label + ") pressed in the browser");
  }
}

void WebViewer::on_iterate() {
  const double now = cycle_time();
  now_s_ = now;
  std::vector<int> pressed;
  {
    std::lock_guard<std::mutex> lock(presses_mutex_);
    pressed.swap(presses_);
  }
  for (int index : pressed) post_button(index);

  const double warp = comms().time_warp();
  if (!last_clock_s_ || (now - *last_clock_s_) / warp >= 1.0) {
    last_clock_s_ = now;
    feed_->on_clock(now, warp);
  }
  if (config_.appcast_request && (!last_request_s_ || now - *last_request_s_ >= kAppCastRequestPeriod_s)) {
    last_request_s_ = now;
    notify("APPCAST_REQ", appcast_request_text());
  }
}

std::string WebViewer::build_report() {
  const EventHub& hub = feed_->hub();
  std::string out;
  out += "URL:       " + url() + "\n";
  out += "Watching:  " + std::to_string(config_.watch.size()) + " variables, " +
         std::to_string(mail_seen_) + " postings heard\n";
  out += "Retained:  " + std::to_string(feed_->retained()) + " postings (" +
         std::to_string(feed_->refused()) + " refused by a bound)\n";
  out += "Viewers:   " + std::to_string(hub.clients()) + " connected, " + std::to_string(hub.served()) +
         " served, " + std::to_string(hub.dropped()) + " dropped for falling behind\n";
  out += "Buttons:   " + std::to_string(config_.buttons.size()) + " configured, " +
         std::to_string(presses_posted_) + " presses posted\n";
  out += "Refused:   " + std::to_string(server_->refused_hosts()) + " requests by a foreign Host name, " +
         std::to_string(server_->refused_posts()) + " posts from another site or without the token\n";
  return out;
}

}  // namespace web_viewer
