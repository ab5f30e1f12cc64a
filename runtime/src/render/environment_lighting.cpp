#include "render/environment_lighting.h"

#include <fmt/format.h>

#include <glm/gtc/matrix_transform.hpp>

#include "image_io/image_io.h"
#include "render/frame_values.h"

namespace facet::runtime {
namespace {

// A uniform environment needs no texels: its prefiltered chain is itself.
constexpr uint32_t kUniformSize = 8;
// A gradient sky varies slowly: 32 texels keep its horizon sharp enough.
constexpr uint32_t kSkySize = 32;
// Irradiance is smooth, but an HDR image's sun is small: the SH projection
// takes more directions than the sky's default.
constexpr int kShHeightNodes = 48, kShAzimuthSteps = 96;

using Radiance = std::function<glm::vec3(const glm::vec3&)>;

EnvironmentLighting from_radiance(const Scene& scene, const Radiance& radiance, uint32_t size, bool sh_from_radiance) {
  EnvironmentLighting out;
  out.cube = prefilter_ggx(cube_from_radiance(radiance, size), {});
  out.ambient = sh_from_radiance ? pack_unity_sh(project_sh(radiance, kShHeightNodes, kShAzimuthSteps))
                                 : ambient_sh(scene);
  return out;
}

Result<Equirect, std::string> read_equirect(const Scene& scene, const SceneEnvironment& e) {
  Result<DecodedImage, std::string> decoded = read_image_file(e.file);
  if (!decoded) return unexpected(fmt::format("{}: environment.file: {}: {}", scene.path, e.file, decoded.error()));
  if (!decoded->floating) {
    // An 8-bit image holds no light brighter than white: reflections and
    // ambient from it would be dim and clipped, silently.
    return unexpected(fmt::format(
        "{}: environment.file: {}: an environment must be a linear HDR image (.hdr or .exr), this one holds 8- or "
        "16-bit integers",
        scene.path, e.file));
  }
  return Equirect{decoded->width, decoded->height, decoded->channels, std::move(decoded->pixels)};
}

}  // namespace

Result<EnvironmentLighting, std::string> environment_lighting(const Scene& scene) {
  if (scene.environment) {
    const SceneEnvironment& e = *scene.environment;
    const bool sh = !scene.ambient_given;
    if (e.file.empty()) {
      const glm::vec3 c = glm::vec3(e.color[0], e.color[1], e.color[2]) * e.intensity;
      return from_radiance(scene, [c](const glm::vec3&) { return c; }, kUniformSize, sh);
    }
    Result<Equirect, std::string> image = read_equirect(scene, e);
    if (!image) return unexpected(image.error());
    // Skybox/Panoramic's _Rotation turns the view ray about +Y by that many degrees.
    const glm::mat3 turn(glm::rotate(glm::mat4(1), glm::radians(e.rotation), glm::vec3(0, 1, 0)));
    const float intensity = e.intensity;
    const Equirect& pixels = *image;
    Radiance radiance = [&](const glm::vec3& d) { return sample_equirect(pixels, turn * d) * intensity; };
    return from_radiance(scene, radiance, uint32_t(e.resolution), sh);
  }
  if (scene.sky) {
    const SkyRadiance sky = linear_sky(*scene.sky);
    const std::optional<SkySun> sun = sky_sun(scene);
    if (!sun) return from_radiance(scene, [&](const glm::vec3& d) { return sky_radiance(sky, d); }, kSkySize, false);
    // The sun's disc is smaller than a texel: each texel averages 8 x 8
    // directions, so that it keeps about its share of the sun's power.
    EnvironmentLighting out;
    out.cube = prefilter_ggx(
        cube_from_radiance([&](const glm::vec3& d) { return sky_radiance(sky, d) + sun_radiance(*sun, d); }, kSkySize,
                           8),
        {});
    out.ambient = ambient_sh(scene);
    return out;
  }
  EnvironmentLighting flat;
  const glm::vec3 c = linear_color(scene.ambient);
  flat.cube = CubeMips{1, {std::vector<float>{}}};
  for (int face = 0; face < 6; ++face) flat.cube.mips[0].insert(flat.cube.mips[0].end(), {c.r, c.g, c.b, 1.0f});
  flat.ambient = ambient_sh(scene);
  return flat;
}

}  // namespace facet::runtime
