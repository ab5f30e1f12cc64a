// About 10 % above each row's measured error (rounded up), the slack the
// study's quadrature and grids need (docs/accuracy.md, "Error budgets").
#include "facet/runtime/accuracy_budgets.h"

#include <array>
#include <utility>

namespace facet::runtime::accuracy {
namespace {

constexpr std::array<std::pair<std::string_view, double>, 26> kBudgets = {{
    {"D_GGX_FP16Safe", 0.004},
    {"V_SmithGGXCorrelatedFast", 0.20},
    {"V_SmithGGXSeparable", 0.22},
    {"V_SchlickGGX", 0.24},
    {"V_SchlickGGXKaris", 0.71},
    {"F_Schlick", 0.039},
    {"F_SchlickSG", 0.0041},
    {"F_Pow4", 0.09},
    {"Fd_Lambert", 1e-5},
    {"Fd_Burley", 0.57},
    {"Fd_Frostbite", 0.0064},
    {"Fd_OrenNayarQualitative", 0.21},
    {"PhongNormalized", 0.00015},
    {"BlinnPhongNormalized", 0.082},
    {"Specular_Ward", 0.98},
    {"Specular_AshikhminShirley", 0.55},
    {"CookTorranceGGX", 0.65},
    {"CookTorranceGGX_Compensated", 0.011},
    {"BRDF1_Unity_PBS", 0.19},
    {"BRDF2_Unity_PBS", 0.91},
    {"BRDF3_Unity_PBS", 1.07},
    {"EnvBRDFApprox", 0.40},
    {"Unity_SurfaceReduction", 0.38},
    {"Unity_BRDF2_SurfaceReduction", 0.022},
    {"Tonemap_ACESNarkowicz", 0.27},
    {"SRGBPow22", 0.037},
}};

}  // namespace

std::optional<double> error_budget(std::string_view row_id) {
  for (const auto& [id, budget] : kBudgets) {
    if (id == row_id) return budget;
  }
  return std::nullopt;
}

}  // namespace facet::runtime::accuracy
