#include "pass_scene.hpp"

#include <cmath>

#include "base/text.hpp"

namespace validation {

namespace {

constexpr const char* kKinds[] = {"H", "B", "B0", "Bh"};
constexpr double kInsideRows_m[] = {-17, -12, -7, -2, 2, 7, 12, 17};
constexpr double kOutsideRows_m[] = {-45, -33, 33, 45};
constexpr double kEdgeDistances_m[] = {3, 7, 12};
constexpr double kEdgeOffsets_m[] = {-10, 0, 10};

double east_end_m(const SceneSpec& spec) {
  return (spec.columns - 1) * spec.spacing_m + spec.margin_m;
}

void add_rows(const SceneSpec& spec, const double* rows, std::size_t row_count,
              const std::string& group, std::vector<SceneObject>& out) {
  for (std::size_t r = 0; r < row_count; ++r) {
    for (int c = 0; c < spec.columns; ++c) {
      const std::string kind = kKinds[(r + static_cast<std::size_t>(c)) % 4];
      out.push_back({"o" + std::to_string(out.size() + 1), kind, group, c * spec.spacing_m,
                     rows[r]});
    }
  }
}

}  // namespace

std::vector<SceneObject> make_scene(const SceneSpec& spec) {
  std::vector<SceneObject> out;
  add_rows(spec, kInsideRows_m, std::size(kInsideRows_m), "inside", out);
  add_rows(spec, kOutsideRows_m, std::size(kOutsideRows_m), "outside", out);
  const double west = -spec.margin_m;
  const double east = east_end_m(spec);
  for (const double d : kEdgeDistances_m) {
    const std::string group = "edge_" + base::format_g(d);
    for (const double y : kEdgeOffsets_m) {
      out.push_back({"o" + std::to_string(out.size() + 1), "H", group, west - d, y});
      out.push_back({"o" + std::to_string(out.size() + 1), "H", group, east + d, y});
    }
  }
  return out;
}

std::string hazard_file_text(const std::vector<SceneObject>& objects, double resemblance) {
  std::string text = "// The validation scene (bench/validation/pass_bench)\n";
  for (const auto& o : objects) {
    text += "hazard = x=" + base::format_g(o.x_m) + ",y=" + base::format_g(o.y_m) +
            ",label=" + o.label + ",type=" + (o.kind == "H" ? "hazard" : "benign");
    if (o.kind == "B0") text += ",hr=0";
    if (o.kind == "Bh") text += ",hr=" + base::format_g(resemblance);
    text += "\n";
  }
  return text;
}

double lane_length_m(const SceneSpec& spec) {
  return east_end_m(spec) + spec.margin_m;
}

TrackPose pose_at(const SceneSpec& spec, double distance_m) {
  const double lane = lane_length_m(spec);
  TrackPose pose;
  pose.lane = static_cast<long long>(std::floor(distance_m / lane));
  const double along = distance_m - static_cast<double>(pose.lane) * lane;
  const bool eastward = pose.lane % 2 == 0;
  pose.x_m = eastward ? -spec.margin_m + along : east_end_m(spec) - along;
  pose.heading_deg = eastward ? 90 : 270;
  return pose;
}

long long passes_by(const SceneObject& object, long long lanes) {
  if (!base::starts_with(object.group, "edge_")) return lanes;
  const bool west = object.x_m < 0;
  // Lane 0 ends at the east end, lane 1 at the west end, ...; the start is at the west end.
  return west ? 1 + lanes / 2 : (lanes + 1) / 2;
}

std::string tallies_csv(const std::vector<std::pair<std::string, std::string>>& header,
                        const Tallies& tallies) {
  std::string text;
  for (const auto& [key, value] : header) text += "# " + key + "=" + value + "\n";
  text += "group,kind,objects,passes,detections,classify_requests,answers,correct\n";
  for (const auto& [key, t] : tallies) {
    text += key + "," + std::to_string(t.objects) + "," + std::to_string(t.passes) + "," +
            std::to_string(t.detections) + "," + std::to_string(t.classify_requests) + "," +
            std::to_string(t.answers) + "," + std::to_string(t.correct) + "\n";
  }
  return text;
}

}  // namespace validation
