#include "facet/reference/cases.h"

namespace facet::reference {

std::vector<FunctionCase> lighting_cases() {
  std::vector<FunctionCase> all = facet_model_cases();
  std::vector<FunctionCase> unity = unity_standard_cases();
  all.insert(all.end(), std::make_move_iterator(unity.begin()), std::make_move_iterator(unity.end()));
  std::vector<FunctionCase> models = lighting_model_cases();
  all.insert(all.end(), std::make_move_iterator(models.begin()), std::make_move_iterator(models.end()));
  return all;
}

}  // namespace facet::reference
