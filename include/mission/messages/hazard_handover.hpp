#pragma once
// HAZARD_HANDOVER (ours; the original Jake mission hard-coded betty's points, manual 13.1): one
// vehicle hands its detections and what it learned about them to another, for reacquisition.
//
// Example (one line):
//   source=archie#dest=betty#prior=0.5#label=75,x=-52,y=-290,evidence=2.841,det=1,miss=0,
//   said_hazard=1,said_benign=0#label=82,x=-41,y=-246,evidence=-1.5347,det=1,miss=0,
//   said_hazard=0,said_benign=1
//
// Posted as HAZARD_HANDOVER and HAZARD_HANDOVER_<DEST> (upper-cased), like the sensor's per-vehicle
// variables. Parts are '#'-separated: `source=` (sender, required), `dest=` (receiver, required),
// `prior=` (the sender's prior P(hazard), in (0, 1), required), then one part per object:
// label (required, no ',' or '#'), x and y (FMT(.,2), required), evidence (FMT(.,6), required):
// the sender's summed log-likelihood ratio ln P(obs | hazard) / P(obs | benign) over everything
// it observed or was handed (belief.hpp), so the receiver adds it to its own prior and evidence
// without counting the sender's prior twice; det, miss, said_hazard, said_benign (whole numbers,
// optional, default 0): the counts behind the evidence, for people and pictures.
// The sender's posterior is logistic(logit(prior) + evidence).
// Hand-overs form a chain (Jake: archie -> betty); a receiver replaces what it had from the same
// sender, so a repeated hand-over never counts twice, but a cycle (A -> B -> A) would.
//
// Parsing: a bad header is an error; a bad object part is skipped with a warning naming the part
// and the field, and the other objects are kept.

#include <string>
#include <string_view>
#include <vector>

#include "hazard/messages/parsed.hpp"
#include "mission/belief.hpp"

namespace mission {

inline constexpr const char* kHazardHandoverVar = "HAZARD_HANDOVER";

struct HandoverObject {
  std::string label;
  double x_m = 0.0;
  double y_m = 0.0;
  Evidence evidence;  ///< log_lr and the counts
};

struct Handover {
  std::string source;
  std::string dest;
  double prior_hazard = kDefaultPriorHazard;
  std::vector<HandoverObject> objects;
  std::vector<std::string> warnings;  ///< skipped object parts (parser only)
};

hazard::Parsed<Handover> parse_handover(std::string_view text);
std::string format_handover(const Handover& handover);
/// "HAZARD_HANDOVER_" + upper-cased destination.
std::string handover_variable_for(std::string_view dest);

}  // namespace mission
