// The closest of a list of names to a mistyped one, for the "did you mean ...?" of an error message.
#pragma once
#include <string>
#include <vector>

namespace rigiddyn {

// The name of `names` at the smallest edit distance (insertions, deletions, substitutions, letters
// compared without case) from `typed`, if that distance is at most a third of the longer of the two
// (and at least 1); "" when none is that close. Ties go to the first in `names`.
std::string closest_name(const std::string& typed, const std::vector<std::string>& names);

// " (did you mean '<closest>'?)" for closest_name(typed, names), or "" when none is close.
std::string did_you_mean(const std::string& typed, const std::vector<std::string>& names);

}  // namespace rigiddyn
