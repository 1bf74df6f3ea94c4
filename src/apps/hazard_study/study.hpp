#pragma once
// hazard_study's run: every setting x every seed, a JSON line each (or the summary).
#include <iosfwd>

#include "study_args.hpp"

namespace hazard_study {

/// Exit status: 0 done, 1 a mission or output problem, 2 a bad --set. Lines go to `out`,
/// warnings and errors (prefixed "hazard_study: ") to `err`.
int run(const Options& options, std::ostream& out, std::ostream& err);

}  // namespace hazard_study
