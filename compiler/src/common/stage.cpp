#include "facet/stage.h"

#include <algorithm>
#include <cctype>
#include <string>

namespace facet {

std::string_view stage_name(Stage s) {
  switch (s) {
    case Stage::vertex: return "vertex";
    case Stage::fragment: return "fragment";
    case Stage::geometry: return "geometry";
    case Stage::hull: return "hull";
    case Stage::domain: return "domain";
  }
  return "unknown";
}

std::optional<Stage> parse_stage(std::string_view name) {
  std::string lower(name);
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (lower == "vertex" || lower == "vert" || lower == "vs") return Stage::vertex;
  if (lower == "fragment" || lower == "frag" || lower == "fs" || lower == "ps" || lower == "pixel") return Stage::fragment;
  if (lower == "geometry" || lower == "geom" || lower == "gs") return Stage::geometry;
  if (lower == "hull" || lower == "tesc" || lower == "hs") return Stage::hull;
  if (lower == "domain" || lower == "tese" || lower == "ds") return Stage::domain;
  return std::nullopt;
}

}  // namespace facet
