#pragma once
/// @brief Spelling help for scene errors: the closest valid name to a misspelt one.
///
/// closestMatch() picks the candidate with the smallest edit distance (Levenshtein, case
/// insensitive) when it is close enough to be a plausible typo; didYouMean() formats it as
/// " (did you mean 'x'?)" or returns "" when nothing is close. joinNames() lists valid choices.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mpmice::core::scene_detail {

int editDistance(std::string_view a, std::string_view b);
std::optional<std::string> closestMatch(std::string_view word, const std::vector<std::string>& candidates);
std::string didYouMean(std::string_view word, const std::vector<std::string>& candidates);
/// "a, b, c" in alphabetical order.
std::string joinNames(std::vector<std::string> names);

}  // namespace mpmice::core::scene_detail
