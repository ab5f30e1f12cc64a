// All the twins of facet's lighting library (stdlib/Facet{BRDF,Disney,IBL,Tonemap,Color}.hlsl).
#pragma once

#include "facet/reference/brdf.h"
#include "facet/reference/color.h"
#include "facet/reference/disney.h"
#include "facet/reference/ibl.h"
#include "facet/reference/tonemap.h"
