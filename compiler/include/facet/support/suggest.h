// "Did you mean": edit distances between names, shared by the stages that
// suggest corrections.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string_view>

namespace facet {

// Restricted Damerau-Levenshtein distance, case-insensitive: a swap of two
// neighbouring letters ("Flaot") is one edit.
size_t edit_distance(std::string_view a, std::string_view b);

// The candidate closest to `word`, if within (length + 2) / 3 edits (at
// least one); ties go to the first. Words over 64 characters get none.
std::optional<std::string_view> closest_name(std::string_view word, std::span<const std::string_view> candidates);

}  // namespace facet
