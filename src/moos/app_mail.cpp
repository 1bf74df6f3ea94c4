// The mail side of a MoosApp cycle (contract in include/moos/app.hpp): sorting the cycle's mail,
// taking the framework's own (APPCAST_REQ, `_async_timing`) and the standing warnings about mail
// and postings the comms dropped.

#include <algorithm>
#include <string>
#include <string_view>

#include "moos/app.hpp"

namespace moos {

namespace {

/// key == name, the first letters compared first: the framework's keys are compared with
/// every message, and NODE_REPORT, most of the mail, has the length of APPCAST_REQ.
bool is_key(const std::string& key, std::string_view name) {
  return key.size() == name.size() && !key.empty() && key[0] == name[0] && key == name;
}

}  // namespace

void MoosApp::handle_mail() {
  const auto by_time = [](const Message& a, const Message& b) { return a.time < b.time; };
  // Mail mostly arrives in time order: checking is cheaper than a merge sort's buffer.
  if (flags_.sort_mail_by_time && !std::is_sorted(mail_.begin(), mail_.end(), by_time))
    std::stable_sort(mail_.begin(), mail_.end(), by_time);
  handle_framework_mail(mail_);
  if (!mail_.empty()) on_new_mail(mail_);
}

void MoosApp::report_dropped_mail() {
  const std::uint64_t dropped = comms_->mail_dropped();
  if (dropped == reported_mail_dropped_) return;
  reported_mail_dropped_ = dropped;
  // One standing warning whose count grows, not one warning per overflow.
  if (!dropped_mail_warning_.empty()) retract_run_warning(dropped_mail_warning_);
  dropped_mail_warning_ = "Mail arrived faster than the app read it: " + std::to_string(dropped) +
                          " oldest unread messages dropped in all (inbox bounds)";
  report_run_warning(dropped_mail_warning_);
}

void MoosApp::report_dropped_postings() {
  const std::uint64_t dropped = comms_->postings_dropped();
  if (dropped == reported_postings_dropped_) return;
  reported_postings_dropped_ = dropped;
  // One standing warning: the count and the latest reason, which names the variable.
  if (!dropped_postings_warning_.empty()) retract_run_warning(dropped_postings_warning_);
  dropped_postings_warning_ = std::to_string(dropped) + " postings not sent in all; the latest: " +
                              comms_->last_post_error();
  report_run_warning(dropped_postings_warning_);
}

void MoosApp::handle_framework_mail(std::vector<Message>& mail) {
  // Nearly every cycle's mail has none: one pass that only compares keys.
  for (auto it = mail.begin(); it != mail.end(); ++it) {
    if (is_key(it->key, kTimingKey) || is_key(it->key, kAppCastRequestKey)) {
      remove_framework_mail(mail, it);
      return;
    }
  }
}

void MoosApp::remove_framework_mail(std::vector<Message>& mail,
                                    std::vector<Message>::iterator first) {
  auto framework = [&](const Message& m) {
    if (is_key(m.key, kTimingKey)) return true;
    if (!is_key(m.key, kAppCastRequestKey)) return false;
    if (auto request = parse_appcast_request(m.sval, community(), settings_.app_name)) {
      requests_[request->key] = Request{curr_time_, *request};
      update_report_every_cycle();
    }
    return true;
  };
  mail.erase(std::remove_if(first, mail.end(), framework), mail.end());
}

}  // namespace moos
