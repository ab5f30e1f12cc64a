// MERL binary BRDFs: Rusinkiewicz half/difference angles, the square-root
// theta_h bins, loading (with the checks a truncated or foreign file needs)
// and writing synthetic files from an analytic BRDF.
#include <fmt/format.h>

#include <bit>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>

#include "brdf_internal.h"
#include "facet/reference/hlsl_math.h"

namespace facet::brdf {
namespace {

using glm::dvec3;
constexpr double kHalfPi = 0.5 * reference::kPi;
const char* const kChannelNames[3] = {"red", "green", "blue"};

uint64_t read_le(const unsigned char* p, int bytes) {
  uint64_t x = 0;
  for (int i = bytes - 1; i >= 0; --i) x = (x << 8) | p[i];
  return x;
}
void write_le(char* out, uint64_t x, int bytes) {
  for (int i = 0; i < bytes; ++i) out[i] = char((x >> (8 * i)) & 0xff);
}
int clamp_index(double x, int n) { return std::clamp(int(x), 0, n - 1); }

Result<std::vector<unsigned char>> read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return failure(fmt::format("{}: cannot open ({})", path, std::strerror(errno)));
  std::vector<unsigned char> bytes(size_t(in.tellg()));
  in.seekg(0);
  if (!in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(bytes.size()))) {
    return failure(fmt::format("{}: read error", path));
  }
  return bytes;
}

// The doubles of a little-endian file (a copy where the host agrees).
std::vector<double> read_doubles(const unsigned char* p, size_t count) {
  std::vector<double> out(count);
  if constexpr (std::endian::native == std::endian::little) {
    std::memcpy(out.data(), p, count * 8);
  } else {
    for (size_t i = 0; i < count; ++i) out[i] = std::bit_cast<double>(read_le(p + 8 * i, 8));
  }
  return out;
}

Result<void> check_layout(const std::string& path, const std::vector<unsigned char>& bytes) {
  if (bytes.size() < 12) {
    return failure(fmt::format("{}: truncated: {} bytes, but a MERL file starts with three int32 dimensions "
                               "(12 bytes)",
                               path, bytes.size()));
  }
  int32_t dims[3];
  for (int i = 0; i < 3; ++i) dims[i] = int32_t(uint32_t(read_le(bytes.data() + 4 * i, 4)));
  if (dims[0] != kMerlThetaH || dims[1] != kMerlThetaD || dims[2] != kMerlPhiD) {
    return failure(fmt::format("{}: dimensions {} x {} x {}, but a MERL file has {} x {} x {} "
                               "(theta_h x theta_d x phi_d)",
                               path, dims[0], dims[1], dims[2], kMerlThetaH, kMerlThetaD, kMerlPhiD));
  }
  if (bytes.size() != kMerlFileBytes) {
    return failure(fmt::format("{}: {} bytes, but a {} x {} x {} MERL file has {} ({})", path, bytes.size(),
                               kMerlThetaH, kMerlThetaD, kMerlPhiD, kMerlFileBytes,
                               bytes.size() < kMerlFileBytes ? "truncated" : "trailing data"));
  }
  return {};
}

dvec3 rotate_z(const dvec3& a, double t) {
  double c = std::cos(t), s = std::sin(t);
  return {a.x * c - a.y * s, a.x * s + a.y * c, a.z};
}
dvec3 rotate_y(const dvec3& a, double t) {
  double c = std::cos(t), s = std::sin(t);
  return {a.x * c + a.z * s, a.y, -a.x * s + a.z * c};
}

}  // namespace

HalfDiff to_half_diff(const dvec3& v, const dvec3& l) {
  dvec3 sum = v + l;
  dvec3 h = glm::dot(sum, sum) > 0.0 ? glm::normalize(sum) : dvec3(0, 0, 1);
  double theta_h = std::acos(std::clamp(h.z, -1.0, 1.0));
  double phi_h = std::atan2(h.y, h.x);
  dvec3 d = rotate_y(rotate_z(glm::normalize(l), -phi_h), -theta_h);
  double phi_d = std::atan2(d.y, d.x);
  if (phi_d < 0.0) phi_d += reference::kPi;
  return {theta_h, std::acos(std::clamp(d.z, -1.0, 1.0)), phi_d};
}

void from_half_diff(const HalfDiff& a, dvec3& v, dvec3& l) {
  dvec3 h(std::sin(a.theta_h), 0.0, std::cos(a.theta_h));
  dvec3 d(std::sin(a.theta_d) * std::cos(a.phi_d), std::sin(a.theta_d) * std::sin(a.phi_d), std::cos(a.theta_d));
  l = rotate_y(d, a.theta_h);
  v = 2.0 * glm::dot(h, l) * h - l;
}

std::size_t merl_index(const HalfDiff& a) {
  int ih = a.theta_h <= 0.0 ? 0 : clamp_index(std::sqrt(a.theta_h / kHalfPi) * kMerlThetaH, kMerlThetaH);
  int id = clamp_index(a.theta_d / kHalfPi * kMerlThetaD, kMerlThetaD);
  int ip = clamp_index(a.phi_d / reference::kPi * kMerlPhiD, kMerlPhiD);
  return std::size_t(ip) + std::size_t(id) * kMerlPhiD + std::size_t(ih) * kMerlPhiD * kMerlThetaD;
}

HalfDiff merl_bin_centre(int ih, int id, int ip) {
  double u = (ih + 0.5) / kMerlThetaH;
  return {u * u * kHalfPi, (id + 0.5) / kMerlThetaD * kHalfPi, (ip + 0.5) / kMerlPhiD * reference::kPi};
}

Result<MerlData> load_merl(const std::string& path) {
  Result<std::vector<unsigned char>> bytes = read_file(path);
  if (!bytes) return unexpected(bytes.error());
  if (Result<void> ok = check_layout(path, *bytes); !ok) return unexpected(ok.error());
  MerlData d;
  d.values = read_doubles(bytes->data() + 12, 3 * kMerlPlane);
  for (std::size_t i = 0; i < d.values.size(); ++i) {
    double x = d.values[i];
    if (!std::isfinite(x)) {
      return failure(fmt::format("{}: entry {} of the {} plane (byte offset {}) is not finite", path,
                                 i % kMerlPlane, kChannelNames[i / kMerlPlane], 12 + 8 * i));
    }
    // Negative entries mark cells MERL did not measure.
    d.values[i] = std::max(x, 0.0) * kMerlScale[i / kMerlPlane];
  }
  return d;
}

dvec3 merl_lookup(const MerlData& d, const dvec3& v, const dvec3& l) {
  std::size_t i = merl_index(to_half_diff(v, l));
  return {d.values[i], d.values[i + kMerlPlane], d.values[i + 2 * kMerlPlane]};
}

Result<void> write_merl(const std::string& path, const BrdfFunction& f) {
  std::vector<double> planes(3 * kMerlPlane);
  for (int ih = 0; ih < kMerlThetaH; ++ih) {
    for (int id = 0; id < kMerlThetaD; ++id) {
      for (int ip = 0; ip < kMerlPhiD; ++ip) {
        HalfDiff a = merl_bin_centre(ih, id, ip);
        dvec3 v, l;
        from_half_diff(a, v, l);
        std::size_t i = merl_index(a);
        bool measurable = v.z > 0.0 && l.z > 0.0;
        dvec3 value = measurable ? f(v, l) : dvec3(0.0);
        for (int c = 0; c < 3; ++c) planes[i + c * kMerlPlane] = measurable ? value[c] / kMerlScale[c] : -1.0;
      }
    }
  }
  std::string bytes(kMerlFileBytes, '\0');
  const int dims[3] = {kMerlThetaH, kMerlThetaD, kMerlPhiD};
  for (int i = 0; i < 3; ++i) write_le(bytes.data() + 4 * i, uint32_t(dims[i]), 4);
  if constexpr (std::endian::native == std::endian::little) {
    std::memcpy(bytes.data() + 12, planes.data(), planes.size() * 8);
  } else {
    for (size_t i = 0; i < planes.size(); ++i) write_le(bytes.data() + 12 + 8 * i, std::bit_cast<uint64_t>(planes[i]), 8);
  }
  return write_file_whole(path, bytes);
}

}  // namespace facet::brdf
