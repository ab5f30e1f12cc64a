#include "facet/runtime/environment.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <system_error>
#include <thread>

#include "facet/runtime/sky_sh.h"

namespace facet::runtime {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

struct FaceCoord {
  int face;
  float s, t;  // 0..1 across the face
};

// Vulkan's cube face selection (the inverse of cube_direction).
FaceCoord face_coord(const glm::vec3& d) {
  glm::vec3 a = glm::abs(d);
  float sc, tc, ma;
  int face;
  if (a.x >= a.y && a.x >= a.z) {
    face = d.x >= 0 ? 0 : 1;
    ma = a.x, sc = d.x >= 0 ? -d.z : d.z, tc = -d.y;
  } else if (a.y >= a.z) {
    face = d.y >= 0 ? 2 : 3;
    ma = a.y, sc = d.x, tc = d.y >= 0 ? d.z : -d.z;
  } else {
    face = d.z >= 0 ? 4 : 5;
    ma = a.z, sc = d.z >= 0 ? d.x : -d.x, tc = -d.y;
  }
  return {face, 0.5f * (sc / ma + 1), 0.5f * (tc / ma + 1)};
}

const float* texel(const std::vector<float>& level, uint32_t size, int face, uint32_t x, uint32_t y) {
  return &level[((size_t(face) * size + y) * size + x) * 4];
}

glm::vec3 bilinear(const std::vector<float>& level, uint32_t size, const FaceCoord& c) {
  float x = std::clamp(c.s * float(size) - 0.5f, 0.0f, float(size - 1));
  float y = std::clamp(c.t * float(size) - 0.5f, 0.0f, float(size - 1));
  uint32_t x0 = uint32_t(x), y0 = uint32_t(y);
  uint32_t x1 = std::min(x0 + 1, size - 1), y1 = std::min(y0 + 1, size - 1);
  float fx = x - float(x0), fy = y - float(y0);
  auto at = [&](uint32_t tx, uint32_t ty) {
    const float* p = texel(level, size, c.face, tx, ty);
    return glm::vec3(p[0], p[1], p[2]);
  };
  return glm::mix(glm::mix(at(x0, y0), at(x1, y0), fx), glm::mix(at(x0, y1), at(x1, y1), fx), fy);
}

uint32_t mip_size(const CubeMips& cube, size_t mip) { return std::max<uint32_t>(cube.size >> mip, 1); }

// A GGX sample around +Z (tangent space) for n = v: the light direction,
// its n.l, and the source lod whose texel solid angle matches the sample's.
struct LobeSample {
  glm::vec3 l;
  float n_dot_l;
  float lod;
};

float radical_inverse(uint32_t i) {
  i = (i << 16) | (i >> 16);
  i = ((i & 0x00ff00ffu) << 8) | ((i & 0xff00ff00u) >> 8);
  i = ((i & 0x0f0f0f0fu) << 4) | ((i & 0xf0f0f0f0u) >> 4);
  i = ((i & 0x33333333u) << 2) | ((i & 0xccccccccu) >> 2);
  i = ((i & 0x55555555u) << 1) | ((i & 0xaaaaaaaau) >> 1);
  return float(double(i) * 2.3283064365386963e-10);
}

std::vector<LobeSample> lobe_samples(float alpha, uint32_t count, uint32_t source_size, float max_lod) {
  std::vector<LobeSample> samples;
  const float a2 = alpha * alpha;
  const float texel_solid_angle = 4 * kPi / (6.0f * float(source_size) * float(source_size));
  for (uint32_t i = 0; i < count; ++i) {
    float u = (float(i) + 0.5f) / float(count);
    float phi = 2 * kPi * radical_inverse(i);
    float cos_h = std::sqrt((1 - u) / (1 + (a2 - 1) * u));
    float sin_h = std::sqrt(std::max(0.0f, 1 - cos_h * cos_h));
    glm::vec3 h(sin_h * std::cos(phi), sin_h * std::sin(phi), cos_h);
    glm::vec3 l = 2 * cos_h * h - glm::vec3(0, 0, 1);
    if (l.z <= 0) continue;
    // pdf(l) = D(h) (n.h) / (4 v.h) = D / 4 with v = n.
    float denom = cos_h * cos_h * (a2 - 1) + 1;
    float d = a2 / (kPi * denom * denom);
    float sample_solid_angle = 4 / (float(count) * d);
    // Krivanek and Colbert's +1: one mip blurrier than the bare ratio, so
    // that neighbouring samples overlap.
    float lod = std::clamp(0.5f * std::log2(sample_solid_angle / texel_solid_angle) + 1, 0.0f, max_lod);
    samples.push_back({l, l.z, lod});
  }
  return samples;
}

void prefilter_face(const CubeMips& source, const std::vector<LobeSample>& lobe, uint32_t size, int face,
                    std::vector<float>& level) {
  for (uint32_t y = 0; y < size; ++y) {
    for (uint32_t x = 0; x < size; ++x) {
      glm::vec3 n = cube_direction(face, (float(x) + 0.5f) / float(size), (float(y) + 0.5f) / float(size));
      glm::vec3 up = std::abs(n.y) < 0.999f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
      glm::vec3 tx = glm::normalize(glm::cross(up, n)), ty = glm::cross(n, tx);
      glm::vec3 sum(0);
      float weight = 0;
      for (const LobeSample& s : lobe) {
        glm::vec3 l = tx * s.l.x + ty * s.l.y + n * s.l.z;
        sum += sample_cube(source, l, s.lod) * s.n_dot_l;
        weight += s.n_dot_l;
      }
      glm::vec3 c = weight > 0 ? sum / weight : sample_cube(source, n, 0);
      float* out = &level[((size_t(face) * size + y) * size + x) * 4];
      out[0] = c.r, out[1] = c.g, out[2] = c.b, out[3] = 1;
    }
  }
}

// One thread a face: each writes its own texels, so the result does not
// depend on the thread count.
std::vector<float> prefiltered_level(const CubeMips& source, uint32_t size, float roughness, uint32_t count) {
  const float alpha = std::max(roughness * roughness, 1e-3f);
  const std::vector<LobeSample> lobe =
      lobe_samples(alpha, count, source.size, float(source.mips.size() - 1));
  std::vector<float> level(size_t(size) * size * 6 * 4);
  if (size < 8) {  // a few texels: threads would cost more than they save
    for (int face = 0; face < 6; ++face) prefilter_face(source, lobe, size, face, level);
    return level;
  }
  int started = 0;
  try {
    std::vector<std::jthread> faces;
    for (int face = 0; face < 6; ++face) {
      faces.emplace_back([&, face] { prefilter_face(source, lobe, size, face, level); });
      started = face + 1;
    }
  } catch (const std::system_error&) {
    // No thread to be had: the faces not started are done here.
  }  // the started threads are joined here, before `level` is read
  for (int face = started; face < 6; ++face) prefilter_face(source, lobe, size, face, level);
  return level;
}

std::vector<float> box_downsample(const std::vector<float>& level, uint32_t size) {
  uint32_t half = std::max<uint32_t>(size / 2, 1);
  std::vector<float> next(size_t(half) * half * 6 * 4);
  for (int face = 0; face < 6; ++face) {
    for (uint32_t y = 0; y < half; ++y) {
      for (uint32_t x = 0; x < half; ++x) {
        for (int c = 0; c < 4; ++c) {
          float sum = 0;
          for (uint32_t k = 0; k < 4; ++k) sum += texel(level, size, face, 2 * x + k % 2, 2 * y + k / 2)[c];
          next[((size_t(face) * half + y) * half + x) * 4 + c] = sum / 4;
        }
      }
    }
  }
  return next;
}

}  // namespace

float unity_mip_roughness(float mip, int steps) {
  // 0.7 r^2 - 1.7 r + m = 0, m = mip / steps in [0, 1]: the smaller root.
  float m = std::clamp(mip / float(steps), 0.0f, 1.0f);
  return std::clamp((1.7f - std::sqrt(std::max(0.0f, 1.7f * 1.7f - 4 * 0.7f * m))) / (2 * 0.7f), 0.0f, 1.0f);
}

CubeMips cube_from_radiance(const std::function<glm::vec3(const glm::vec3&)>& radiance, uint32_t size,
                            uint32_t supersample) {
  CubeMips cube{size, {}};
  std::vector<float> level(size_t(size) * size * 6 * 4);
  const uint32_t n = std::max<uint32_t>(supersample, 1);
  for (int face = 0; face < 6; ++face) {
    for (uint32_t y = 0; y < size; ++y) {
      for (uint32_t x = 0; x < size; ++x) {
        glm::vec3 c(0);
        for (uint32_t sy = 0; sy < n; ++sy) {
          for (uint32_t sx = 0; sx < n; ++sx) {
            const float s = (float(x) + (float(sx) + 0.5f) / float(n)) / float(size);
            const float t = (float(y) + (float(sy) + 0.5f) / float(n)) / float(size);
            c += radiance(cube_direction(face, s, t));
          }
        }
        c /= float(n * n);
        float* out = &level[((size_t(face) * size + y) * size + x) * 4];
        out[0] = c.r, out[1] = c.g, out[2] = c.b, out[3] = 1;
      }
    }
  }
  cube.mips.push_back(std::move(level));
  build_box_mips(cube);
  return cube;
}

void build_box_mips(CubeMips& cube) {
  cube.mips.resize(1);
  for (uint32_t s = cube.size; s > 1; s /= 2) cube.mips.push_back(box_downsample(cube.mips.back(), s));
}

glm::vec3 sample_cube(const CubeMips& cube, const glm::vec3& direction, float lod) {
  const FaceCoord c = face_coord(direction);
  lod = std::clamp(lod, 0.0f, float(cube.mips.size() - 1));
  size_t lower = size_t(lod);
  size_t upper = std::min(lower + 1, cube.mips.size() - 1);
  glm::vec3 a = bilinear(cube.mips[lower], mip_size(cube, lower), c);
  if (upper == lower) return a;
  return glm::mix(a, bilinear(cube.mips[upper], mip_size(cube, upper), c), lod - float(lower));
}

CubeMips prefilter_ggx(const CubeMips& source, const PrefilterOptions& options) {
  CubeMips out{source.size, {source.mips.front()}};
  for (size_t m = 1; m < source.mips.size(); ++m) {
    const uint32_t size = mip_size(source, m);
    if (int(m) > options.steps) {
      out.mips.push_back(box_downsample(out.mips.back(), mip_size(source, m - 1)));
      continue;
    }
    out.mips.push_back(prefiltered_level(source, size, unity_mip_roughness(float(m), options.steps), options.samples));
  }
  return out;
}

glm::vec3 ggx_lobe_reference(const std::function<glm::vec3(const glm::vec3&)>& radiance, const glm::vec3& n,
                             float roughness, uint32_t height_steps) {
  const float alpha = roughness * roughness, a2 = alpha * alpha;
  glm::vec3 up = std::abs(n.y) < 0.999f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  glm::vec3 tx = glm::normalize(glm::cross(up, n)), ty = glm::cross(n, tx);
  glm::dvec3 sum(0);
  double weight = 0;
  for (uint32_t i = 0; i < height_steps; ++i) {
    for (uint32_t j = 0; j < 64; ++j) {  // a regular grid: no pattern shared with the prefilter's Hammersley points
      float u = (float(i) + 0.5f) / float(height_steps), phi = 2 * kPi * (float(j) + 0.5f) / 64;
      float cos_h = std::sqrt((1 - u) / (1 + (a2 - 1) * u)), sin_h = std::sqrt(1 - cos_h * cos_h);
      glm::vec3 h = tx * (sin_h * std::cos(phi)) + ty * (sin_h * std::sin(phi)) + n * cos_h;
      glm::vec3 l = 2 * glm::dot(n, h) * h - n;
      float n_dot_l = glm::dot(n, l);
      if (n_dot_l <= 0) continue;
      sum += glm::dvec3(radiance(l)) * double(n_dot_l);
      weight += n_dot_l;
    }
  }
  return weight > 0 ? glm::vec3(sum / weight) : radiance(n);
}

glm::vec3 sample_equirect(const Equirect& image, const glm::vec3& direction) {
  glm::vec3 d = glm::normalize(direction);
  float u = 0.5f - std::atan2(d.z, d.x) / (2 * kPi);
  float v = std::acos(std::clamp(d.y, -1.0f, 1.0f)) / kPi;  // 0 looking up: row 0
  float x = u * float(image.width) - 0.5f;
  float y = std::clamp(v * float(image.height) - 0.5f, 0.0f, float(image.height - 1));
  float fx = x - std::floor(x), fy = y - std::floor(y);
  auto wrap = [&](int i) { return uint32_t(((i % int(image.width)) + int(image.width)) % int(image.width)); };
  uint32_t x0 = wrap(int(std::floor(x))), x1 = wrap(int(std::floor(x)) + 1);
  uint32_t y0 = uint32_t(y), y1 = std::min(y0 + 1, image.height - 1);
  auto at = [&](uint32_t px, uint32_t py) {
    const float* p = &image.pixels[(size_t(py) * image.width + px) * size_t(image.channels)];
    return image.channels >= 3 ? glm::vec3(p[0], p[1], p[2]) : glm::vec3(p[0]);
  };
  return glm::mix(glm::mix(at(x0, y0), at(x1, y0), fx), glm::mix(at(x0, y1), at(x1, y1), fx), fy);
}

}  // namespace facet::runtime
