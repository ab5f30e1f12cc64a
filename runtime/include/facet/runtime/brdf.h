// facet brdf: the views of Disney's BRDF Explorer (lit sphere, polar plot of
// the lobe, MERL half/difference slice, directional albedo) evaluated on the
// double-precision CPU twins of the stdlib's lighting models (facet_reference),
// and a loader for MERL binary BRDFs. docs/brdf-explorer.md.
//
// Conventions: a BRDF is evaluated in the local frame n = +z, tangent +x,
// bitangent +y; it is returned without the cosine, in linear RGB, and is zero
// when v or l lies below the surface.
#pragma once

#include <glm/glm.hpp>

#include <cstddef>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "facet/result.h"

namespace facet::brdf {

using BrdfFunction = std::function<glm::dvec3(const glm::dvec3& v, const glm::dvec3& l)>;

// One model to plot: its label spells out every parameter
// ("ggx:roughness=0.3,f0=0.04"), so a legend says exactly what was drawn.
struct Model {
  std::string label;
  BrdfFunction f;
};

// ---- the registry: model families over the twins ----
struct ParamInfo {
  std::string name;
  int components = 1;  // 1 (a number) or 3 (a colour, written r/g/b or one number for grey)
  double min = 0, max = 1;
  glm::dvec3 default_value{0.0};
  std::string help;
};
struct FamilyInfo {
  std::string name;
  std::string twins;  // the facet::reference functions it calls
  std::vector<ParamInfo> params;
};
// Every family, "merl" (whose spec is merl:PATH) included.
const std::vector<FamilyInfo>& model_families();
// "family" or "family:name=value,name=value" or "merl:PATH". Errors name the
// family, the parameter and the accepted names or range.
Result<Model> parse_model(const std::string& spec);

// ---- the views' data ----
enum class Channel { luminance, red, green, blue };
double channel_value(const glm::dvec3& rgb, Channel c);  // luminance: Rec. 709 weights

// Linear RGB, row-major, top row first.
struct Image {
  int width = 0, height = 0;
  std::vector<float> rgb;
  glm::dvec3 at(int x, int y) const;
};

// Directional albedo E(v) = integral of f(v, l) <n.l> dl, on a half-vector grid
// of quadrature x quadrature points (theta_h = (pi/2) s^2 crowds them near
// h = n, where specular lobes peak).
glm::dvec3 directional_albedo(const BrdfFunction& f, const glm::dvec3& v, int quadrature);

// Orthographic view of a unit sphere along -z (v = +z), filling the image.
// Directional: one light at l = (-sin ti, 0, cos ti) (ti = incidence_deg from
// the view, on the left), irradiance pi on a surface facing it, so a white
// Lambert facing it shows 1.
// Furnace: a uniform white environment of radiance 1, each pixel integrated
// (directional_albedo in the pixel's frame): a lossless BRDF is 1 everywhere.
// The tangent of each pixel's frame is world +x made orthogonal to n.
struct LitSphereOptions {
  int size = 256;
  double incidence_deg = 45;
  bool furnace = false;
  int quadrature = 48;
};
Image render_lit_sphere(const Model& m, const LitSphereOptions& o);
// The normal and the view vector (in the pixel's local frame) of pixel (x, y),
// or false outside the sphere.
bool lit_sphere_pixel(int x, int y, int size, glm::dvec3& normal, glm::dvec3& local_v);

// MERL-style slice: column i at theta_h = (i + 0.5)/size * 90 deg (linear),
// row j from the bottom at theta_d = (j + 0.5)/size * 90 deg, at phi_d; the
// pixel holds pi * f, which is 1 for a white Lambert.
struct SliceOptions {
  int size = 256;
  double phi_d_deg = 90;
};
Image render_slice(const Model& m, const SliceOptions& o);

// The lobe in the plane of incidence (xz): light at l = (-sin ti, 0, cos ti),
// view at signed theta_v in [-90, 90] deg (positive towards +x, the mirror
// side). radius = f(v, l) * cos(theta_v): the reflected intensity per unit
// irradiance, so Lambert's cosine law makes Lambert a circle of diameter
// albedo/pi through the origin. x = radius sin(theta_v), y = radius cos(theta_v).
struct PolarPoint {
  double theta_deg = 0, radius = 0, x = 0, y = 0;
};
std::vector<PolarPoint> polar_curve(const Model& m, double incidence_deg, Channel c, int samples = 361);

struct AlbedoPoint {
  double theta_deg = 0;
  glm::dvec3 albedo{0.0};
};
// theta_v = 0 ... max_theta_deg in `points` even steps.
std::vector<AlbedoPoint> albedo_curve(const Model& m, int points = 90, double max_theta_deg = 89,
                                      int quadrature = 128);

// ---- MERL binary BRDFs (Matusik et al. 2003) ----
// int32 dims (90, 90, 180), then 3 channel planes of 90*90*180 float64,
// little-endian; stored value * scale = BRDF; negative = unmeasured.
inline constexpr int kMerlThetaH = 90, kMerlThetaD = 90, kMerlPhiD = 180;
inline constexpr std::size_t kMerlPlane = std::size_t(kMerlThetaH) * kMerlThetaD * kMerlPhiD;
inline constexpr std::size_t kMerlFileBytes = 12 + 3 * kMerlPlane * 8;  // 34,992,012
inline constexpr double kMerlScale[3] = {1.0 / 1500.0, 1.15 / 1500.0, 1.66 / 1500.0};

struct HalfDiff {
  double theta_h = 0, theta_d = 0, phi_d = 0;
};
// Rusinkiewicz's half/difference angles of (l, v); the difference vector is l
// seen from h's frame, phi_d folded to [0, pi) (reciprocity).
HalfDiff to_half_diff(const glm::dvec3& v, const glm::dvec3& l);
// A (v, l) pair with these angles (phi_h = 0).
void from_half_diff(const HalfDiff& a, glm::dvec3& v, glm::dvec3& l);
// The flat index of the bin holding `a`, with MERL's square-root theta_h bins.
std::size_t merl_index(const HalfDiff& a);
// The angles of the centre of bin (ih, id, ip).
HalfDiff merl_bin_centre(int ih, int id, int ip);

struct MerlData {
  std::vector<double> values;  // 3 planes, already scaled, negative entries set to 0
};
// Errors say which file and what is wrong (missing, truncated header, dims,
// size, non-finite entry).
Result<MerlData> load_merl(const std::string& path);
glm::dvec3 merl_lookup(const MerlData& d, const glm::dvec3& v, const glm::dvec3& l);
// A MERL file of f sampled at the bin centres (stored as f / scale), written
// whole or not at all.
Result<void> write_merl(const std::string& path, const BrdfFunction& f);

// ---- the command ----
// `facet brdf MODEL... --view lit-sphere|polar|slice|albedo -o out.png|out.svg`;
// `args` are the words after `brdf`. Returns the exit code: 0, or 1 with a
// message on `err` (and no output file) for bad arguments, models or files.
int run_brdf_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace facet::brdf
