// The Pareto chart with its titles given: the study's chart
// (study_chart_svg) and the budget search's (budget_chart_svg) are one drawing.
#pragma once

#include <string>

#include "facet/runtime/accuracy.h"

namespace facet::runtime::accuracy {

struct ChartTitles {
  std::string title;
  std::string subtitle;   // "" for the study's timed-pass line
  std::string time_axis;  // the x axis' title
};
std::string pareto_chart_svg(const Study& study, const ChartTitles& titles);

}  // namespace facet::runtime::accuracy
