// GPU textures and samplers of a frame: the built-in textures, files read
// through image_io (OpenImageIO) (cached by path and colour space), fallback images for
// every dimension, and the environment cube that stands in for a reflection
// probe (the flat ambient colour or the procedural sky).
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

#include "facet/result.h"
#include "facet/runtime/environment.h"
#include "facet/runtime/image.h"
#include "facet/runtime/scene.h"

namespace facet::runtime {

struct LoadedTexture {
  Image image;
  uint32_t width = 1, height = 1;
  std::vector<std::vector<std::byte>> mips;  // the uploaded texels, kept only for frame captures
};

class Resources {
 public:
  explicit Resources(const Context& context) : context_(context) {}
  ~Resources();
  Resources(const Resources&) = delete;
  Resources& operator=(const Resources&) = delete;

  // A 2D texture for a material slot; errors name the file.
  Result<const LoadedTexture*, std::string> texture(const SceneTexture& ref);
  // An image for a resource of dimension `dim` ("2D", "Cube", "3D") that
  // nothing else binds: white, or for "Cube" the environment.
  Result<const Image*, std::string> fallback(std::string_view dim, bool arrayed);
  // The environment cube of these mips (a reflection probe's chain,
  // environment_lighting), RGBA16F, replacing the flat one.
  Result<const Image*, std::string> environment_cube(const CubeMips& cube);
  // A reflection probe's cube, kept for the frame (RGBA16F, its mips).
  Result<const Image*, std::string> add_probe(const CubeMips& cube);
  // Loads every light's cookie before recording; errors name
  // "<scene>: lights[i].cookie".
  Result<void, std::string> load_cookies(const Scene& scene);
  // The light textures Unity's own AutoLight.cginc samples, where facet's
  // stdlib computes the same falloffs analytically (FacetLight.hlsl), so
  // that programs built against Unity's include files light alike:
  // `falloff` is the attenuation at u = distance^2 / range^2 (Unity's
  // _LightTextureB0, and a point light's _LightTexture0); `spot_cone` is a
  // spot light's cookie without a cookie file, the smooth cone between the
  // outer and inner angles in the projective uv of unity_WorldToLight.
  // Both are sampled through clamp_sampler (clamped: beyond the range, and
  // outside the cone, is 0).
  Result<const Image*, std::string> light_falloff();
  Result<const Image*, std::string> spot_cone(float cos_outer, float cos_inner);
  bool clamped(const Image* image) const;
  // Created on first use and kept; an error when the device refuses one.
  Result<VkSampler, std::string> sampler();        // trilinear, repeat
  Result<VkSampler, std::string> clamp_sampler();  // bilinear, clamp to edge
  Result<VkSampler, std::string> point_sampler();  // nearest, clamp to edge: depth images (shadow maps)

  size_t textures_loaded() const { return files_loaded_; }

  // Keep the texels of textures made from now on, for pixels_of.
  void keep_pixels(bool keep) { keep_pixels_ = keep; }
  // The uploaded texels of an image made here (empty when not kept or not ours).
  const std::vector<std::vector<std::byte>>* pixels_of(const Image* image) const;

 private:
  Result<LoadedTexture, std::string> solid(const std::array<float, 4>& rgba, VkImageViewType view, uint32_t layers,
                                           bool srgb);
  Result<LoadedTexture, std::string> load_file(const SceneTexture& ref);
  Result<const Image*, std::string> made_texture(std::pair<float, float> key, uint32_t width, uint32_t height,
                                                 const std::function<float(float, float)>& value);

  const Context& context_;
  // name, sRGB, alpha from grey, glTF metallic-roughness factors
  std::map<std::tuple<std::string, bool, bool, std::optional<std::array<float, 2>>>, std::unique_ptr<LoadedTexture>>
      textures_;
  std::map<std::string, std::unique_ptr<LoadedTexture>> fallbacks_;
  std::unique_ptr<LoadedTexture> environment_;
  std::vector<std::unique_ptr<LoadedTexture>> probes_;
  std::map<std::pair<float, float>, std::unique_ptr<LoadedTexture>> light_textures_;  // (0, 0): the falloff
  VkSampler sampler_ = VK_NULL_HANDLE, point_sampler_ = VK_NULL_HANDLE, clamp_sampler_ = VK_NULL_HANDLE;
  size_t files_loaded_ = 0;
  bool keep_pixels_ = false;
};

}  // namespace facet::runtime
