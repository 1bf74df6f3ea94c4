#include "retained_state.hpp"

#include <algorithm>

#include "base/text.hpp"

namespace web_viewer {

namespace {

constexpr std::string_view kAppCastSeparator = "!@#";

bool is_view_variable(const std::string& var) { return base::starts_with(var, "VIEW_"); }

/// False only for an explicit active=false, in any case (pMarineViewer's removal; the page
/// reads it the same way).
bool is_active(const std::string& value) { return !base::iequals(field_of(value, "active"), "false"); }

template <typename Ring>
void push_bounded(Ring& ring, typename Ring::value_type item, std::size_t bound) {
  ring.push_back(std::move(item));
  while (ring.size() > bound) ring.pop_front();
}

}  // namespace

std::string field_of(const std::string& value, std::string_view key) {
  for (const base::KeyValue& kv : base::split_key_values(value, ',', true))
    if (kv.has_equals && base::iequals(kv.key, key)) return std::string(kv.value);
  return std::string();
}

std::string appcast_field(const std::string& value, std::string_view key) {
  std::size_t pos = 0;
  while (pos <= value.size()) {
    std::size_t end = value.find(kAppCastSeparator, pos);
    if (end == std::string::npos) end = value.size();
    const std::string_view item(value.data() + pos, end - pos);
    const auto eq = item.find('=');
    if (eq != std::string_view::npos && base::iequals(item.substr(0, eq), key))
      return std::string(item.substr(eq + 1));
    pos = end + kAppCastSeparator.size();
  }
  return std::string();
}

void RetainedState::apply(const Mail& mail) {
  if (!mail.is_double && mail.sval.size() > limits_.max_value_bytes) {
    ++refused_;
    return;
  }
  if (!mail.is_double && is_view_variable(mail.var)) {
    apply_view(mail);
  } else if (!mail.is_double && mail.var == "NODE_REPORT") {
    apply_node_report(mail);
  } else if (!mail.is_double && mail.var == "APPCAST") {
    apply_appcast(mail);
  } else {
    latest_[{mail.var, mail.is_double ? std::string() : field_of(mail.sval, "vname")}] = entry(mail);
  }
}

void RetainedState::apply_view(const Mail& mail) {
  const std::string label = field_of(mail.sval, "label");
  const bool active = is_active(mail.sval);
  if (label.empty()) {
    if (active) push_bounded(unlabelled_[mail.var], entry(mail), limits_.unlabelled_ring);
    return;
  }
  Labelled& kept = labelled_[mail.var];
  auto found = kept.seq_of_label.find(label);
  if (found != kept.seq_of_label.end()) {
    kept.by_seq.erase(found->second);
    kept.seq_of_label.erase(found);
  }
  if (!active) return;
  const std::uint64_t seq = next_seq_++;
  kept.seq_of_label[label] = seq;
  kept.by_seq[seq] = mail;
  if (kept.by_seq.size() > limits_.max_labels) {  // evict the oldest label
    const auto oldest = kept.by_seq.begin();
    kept.seq_of_label.erase(field_of(oldest->second.sval, "label"));
    kept.by_seq.erase(oldest);
  }
}

void RetainedState::apply_node_report(const Mail& mail) {
  const std::string name = field_of(mail.sval, "NAME");
  auto trail = trails_.find(name);
  if (trail == trails_.end()) {
    if (trails_.size() >= limits_.max_vehicles) {
      ++refused_;
      return;
    }
    trail = trails_.emplace(name, std::deque<Entry>()).first;
  }
  push_bounded(trail->second, entry(mail), limits_.trail_length);
}

void RetainedState::apply_appcast(const Mail& mail) {
  std::pair<std::string, std::string> key(appcast_field(mail.sval, "node"),
                                          appcast_field(mail.sval, "proc"));
  if (appcasts_.size() >= limits_.max_appcasts && appcasts_.count(key) == 0) {
    ++refused_;
    return;
  }
  appcasts_[std::move(key)] = entry(mail);
}

std::size_t RetainedState::size() const {
  std::size_t n = appcasts_.size() + latest_.size();
  for (const auto& [var, kept] : labelled_) n += kept.by_seq.size();
  for (const auto& [var, ring] : unlabelled_) n += ring.size();
  for (const auto& [name, trail] : trails_) n += trail.size();
  return n;
}

std::vector<Mail> RetainedState::snapshot() const {
  std::vector<std::pair<std::uint64_t, const Mail*>> all;
  all.reserve(size());
  auto add = [&](std::uint64_t seq, const Mail& mail) { all.emplace_back(seq, &mail); };
  for (const auto& [var, kept] : labelled_)
    for (const auto& [seq, mail] : kept.by_seq) add(seq, mail);
  for (const auto& [var, ring] : unlabelled_)
    for (const Entry& e : ring) add(e.seq, e.mail);
  for (const auto& [name, trail] : trails_)
    for (const Entry& e : trail) add(e.seq, e.mail);
  for (const auto& [key, e] : appcasts_) add(e.seq, e.mail);
  for (const auto& [var, e] : latest_) add(e.seq, e.mail);
  std::sort(all.begin(), all.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });

  std::vector<Mail> out;
  out.reserve(all.size());
  for (const auto& [seq, mail] : all) {
    if (!mail->is_double && is_view_variable(mail->var)) {
      const auto duration_s = base::parse_number(field_of(mail->sval, "duration"));
      const double posted_s = base::parse_number(field_of(mail->sval, "time")).value_or(mail->time_s);
      if (duration_s && *duration_s > 0 && posted_s + *duration_s < clock_s_) continue;
    }
    out.push_back(*mail);
  }
  return out;
}

}  // namespace web_viewer
