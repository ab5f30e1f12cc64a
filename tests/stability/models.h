// The lighting models of the stability suite: the rows of facet's model table
// (facet/reference/models.h) that have a point form, each as HLSL statements
// for the GPU evaluator and as its CPU twin, both computing the light
// reflected towards v for a light of intensity `intensity` from l:
// f(v, l) <n.l> intensity (Unity's tiers in their own convention, specular
// times pi, diffuse not divided by pi). The evaluator's point layout is the
// table's (kModelInputs floats); the result is r.xyz.
#pragma once

#include <string>
#include <vector>

#include "facet/reference/models.h"

namespace facet::stability {

inline constexpr int kInputs = reference::kModelInputs;
using Inputs = reference::ModelPoint;
using Energy = reference::Energy;
using Model = reference::LightingModel;
using reference::evaluator_hlsl;
using reference::pack;
using reference::unpack;

// Every row of the table with HLSL, in the table's order.
const std::vector<Model>& models();
const Model& model(const std::string& name);  // by name; throws std::out_of_range

}  // namespace facet::stability
