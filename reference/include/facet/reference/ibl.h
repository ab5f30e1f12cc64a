// Double-precision twin of stdlib/FacetIBL.hlsl, plus what only the CPU does:
// building the DFG table and projecting an environment onto SH9.
#pragma once

#include "facet/reference/brdf.h"

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace facet::reference {

inline double FacetPerceptualRoughnessToMipLevel(double perceptualRoughness, double maxMipLevel) {
  return saturate(perceptualRoughness) * maxMipLevel;
}
inline double FacetPerceptualRoughnessToMipLevelUnity(double perceptualRoughness, double mipSteps) {
  double r = saturate(perceptualRoughness);
  return r * (1.7 - 0.7 * r) * mipSteps;
}

inline glm::dvec2 FacetEnvBRDFApproxAB(double perceptualRoughness, double NoV) {
  const glm::dvec4 c0(-1.0, -0.0275, -0.572, 0.022);
  const glm::dvec4 c1(1.0, 0.0425, 1.04, -0.04);
  glm::dvec4 r = perceptualRoughness * c0 + c1;
  double a004 = std::min(r.x * r.x, std::exp2(-9.28 * NoV)) * r.x + r.y;
  glm::dvec2 AB = glm::dvec2(-1.04, 1.04) * a004 + glm::dvec2(r.z, r.w);
  return glm::max(AB, glm::dvec2(0.0));
}
inline glm::dvec3 FacetEnvBRDFApprox(const glm::dvec3& f0, double perceptualRoughness, double NoV) {
  glm::dvec2 AB = FacetEnvBRDFApproxAB(perceptualRoughness, NoV);
  return f0 * AB.x + AB.y;
}

inline glm::dvec3 FacetEnvBRDF_DFG(const glm::dvec3& f0, double f90, const glm::dvec2& dfg) {
  return f0 * (dfg.y - dfg.x) + f90 * dfg.x;
}

inline uint32_t reverse_bits(uint32_t i) {
  i = (i << 16) | (i >> 16);
  i = ((i & 0x00ff00ffu) << 8) | ((i & 0xff00ff00u) >> 8);
  i = ((i & 0x0f0f0f0fu) << 4) | ((i & 0xf0f0f0f0u) >> 4);
  i = ((i & 0x33333333u) << 2) | ((i & 0xccccccccu) >> 2);
  i = ((i & 0x55555555u) << 1) | ((i & 0xaaaaaaaau) >> 1);
  return i;
}
inline double FacetRadicalInverse(uint32_t i) { return double(reverse_bits(i)) * 2.3283064365386963e-10; }

inline glm::dvec2 FacetDFG_Integrate(double NoV, double alpha, uint32_t sampleCount) {
  glm::dvec3 v(std::sqrt(saturate((1.0 - NoV) * (1.0 + NoV))), 0.0, NoV);
  double a2 = alpha * alpha;
  glm::dvec2 sum(0.0);
  for (uint32_t i = 0; i < sampleCount; ++i) {
    double u = (double(i) + 0.5) / double(sampleCount);
    double phi = 2.0 * kPi * FacetRadicalInverse(i);
    double cosH = std::sqrt((1.0 - u) / (1.0 + (a2 - 1.0) * u));
    double sinH = std::sqrt(saturate((1.0 - cosH) * (1.0 + cosH)));
    glm::dvec3 h(sinH * std::cos(phi), sinH * std::sin(phi), cosH);
    double VoH = glm::dot(v, h);
    glm::dvec3 l = 2.0 * VoH * h - v;
    double NoL = l.z;
    if (NoL > 0.0 && VoH > 0.0) {
      double w = 4.0 * FacetV_SmithGGXCorrelated(NoV, NoL, alpha) * NoL * VoH / cosH;
      double fc = FacetPow5(1.0 - VoH);
      sum += glm::dvec2(w * fc, w);
    }
  }
  return sum / double(sampleCount);
}

// The DFG table as the runtime uploads it (RG16F): texel (i, j) holds
// FacetDFG_Integrate at NoV = (i + 0.5)/size and perceptual roughness
// (j + 0.5)/size (alpha = r^2, clamped to FACET_MIN_ALPHA), row-major.
struct DfgTable {
  int size = 0;
  std::vector<glm::dvec2> texels;
  glm::dvec2 at(int i, int j) const { return texels[size_t(j) * size_t(size) + size_t(i)]; }
};
inline DfgTable FacetBuildDfgTable(int size, uint32_t sampleCount) {
  DfgTable t;
  t.size = size;
  t.texels.resize(size_t(size) * size_t(size));
  for (int j = 0; j < size; ++j) {
    double r = (j + 0.5) / size;
    for (int i = 0; i < size; ++i) {
      double NoV = (i + 0.5) / size;
      t.texels[size_t(j) * size_t(size) + size_t(i)] = FacetDFG_Integrate(NoV, FacetClampAlpha(r * r), sampleCount);
    }
  }
  return t;
}

inline double FacetSH9Irradiance(const glm::dvec3& n, const double sh[9]) {
  const double c0 = 0.886226925452758;
  const double c1 = 1.023326707946489;
  const double c2 = 0.858085715393580;
  const double c3 = 0.247707956747363;
  const double c4 = 0.429042857696790;
  double e = c0 * sh[0] + c1 * (sh[1] * n.y + sh[2] * n.z + sh[3] * n.x) +
             c2 * (sh[4] * n.x * n.y + sh[5] * n.y * n.z + sh[7] * n.x * n.z) +
             c3 * sh[6] * (3.0 * n.z * n.z - 1.0) + c4 * sh[8] * (n.x * n.x - n.y * n.y);
  return std::max(e, 0.0);
}
inline glm::dvec3 FacetSH9Irradiance(const glm::dvec3& n, const glm::dvec3 sh[9]) {
  double r[9], g[9], b[9];
  for (int i = 0; i < 9; ++i) {
    r[i] = sh[i].r;
    g[i] = sh[i].g;
    b[i] = sh[i].b;
  }
  return {FacetSH9Irradiance(n, r), FacetSH9Irradiance(n, g), FacetSH9Irradiance(n, b)};
}

// The 9 real SH basis functions at unit direction d, in FacetSH9Irradiance's order.
inline std::array<double, 9> sh9_basis(const glm::dvec3& d) {
  return {0.282094791773878, 0.488602511902920 * d.y, 0.488602511902920 * d.z, 0.488602511902920 * d.x,
          1.092548430592079 * d.x * d.y, 1.092548430592079 * d.y * d.z,
          0.315391565252520 * (3.0 * d.z * d.z - 1.0), 1.092548430592079 * d.x * d.z,
          0.546274215296040 * (d.x * d.x - d.y * d.y)};
}
// Projects radiance(d) onto SH9 by midpoint quadrature, uniform in cos(theta)
// (d omega = dz dphi), which integrates low-order polynomials in z nearly
// exactly and trigonometric polynomials in phi of degree < phiSteps exactly.
inline std::array<double, 9> project_sh9(const std::function<double(const glm::dvec3&)>& radiance, int zSteps,
                                         int phiSteps = 32) {
  std::array<double, 9> c{};
  double dz = 2.0 / zSteps, dPhi = 2.0 * kPi / phiSteps;
  for (int i = 0; i < zSteps; ++i) {
    double z = -1.0 + (i + 0.5) * dz;
    double s = std::sqrt(std::max(0.0, 1.0 - z * z));
    for (int j = 0; j < phiSteps; ++j) {
      double phi = (j + 0.5) * dPhi;
      glm::dvec3 d(s * std::cos(phi), s * std::sin(phi), z);
      double w = radiance(d) * dz * dPhi;
      std::array<double, 9> y = sh9_basis(d);
      for (int k = 0; k < 9; ++k) c[k] += w * y[k];
    }
  }
  return c;
}

}  // namespace facet::reference
