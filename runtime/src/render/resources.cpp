#include "render/resources.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/gtc/packing.hpp>

#include "facet/runtime/material.h"
#include "facet/runtime/vulkan_context.h"
#include "image_io/image_io.h"

namespace facet::runtime {
namespace {

// Built-in textures as in Unity: linear values of the texel.
std::array<float, 4> builtin_rgba(const std::string& name) {
  if (name == "black") return {0, 0, 0, 0};
  if (name == "gray" || name == "grey") return {0.5f, 0.5f, 0.5f, 0.5f};
  if (name == "bump") return {0.5f, 0.5f, 1, 1};  // a flat normal, (0, 0, 1) after UnpackNormal
  if (name == "red") return {1, 0, 0, 1};
  return {1, 1, 1, 1};
}

// Halves a float RGBA image (box filter, odd edges clamped), in linear space.
std::vector<float> downsample(const std::vector<float>& src, uint32_t w, uint32_t h, uint32_t& out_w, uint32_t& out_h) {
  out_w = std::max(1u, w / 2);
  out_h = std::max(1u, h / 2);
  std::vector<float> dst(size_t(out_w) * out_h * 4);
  for (uint32_t y = 0; y < out_h; ++y) {
    for (uint32_t x = 0; x < out_w; ++x) {
      for (int c = 0; c < 4; ++c) {
        float sum = 0;
        for (uint32_t dy = 0; dy < 2; ++dy) {
          for (uint32_t dx = 0; dx < 2; ++dx) {
            uint32_t sx = std::min(w - 1, 2 * x + dx), sy = std::min(h - 1, 2 * y + dy);
            sum += src[(size_t(sy) * w + sx) * 4 + c];
          }
        }
        dst[(size_t(y) * out_w + x) * 4 + c] = sum / 4;
      }
    }
  }
  return dst;
}

std::vector<std::byte> encode(const std::vector<float>& linear, VkFormat format) {
  std::vector<std::byte> out;
  if (format == VK_FORMAT_R16G16B16A16_SFLOAT) {
    out.resize(linear.size() * 2);
    for (size_t i = 0; i < linear.size(); ++i) {
      // Half floats end at 65504: an HDR file's unclipped sun would become
      // inf, and filtering inf next to 0 gives NaN.
      float v = std::isnan(linear[i]) ? 0.0f : std::clamp(linear[i], -65504.0f, 65504.0f);
      uint16_t h = glm::packHalf1x16(v);
      std::memcpy(out.data() + 2 * i, &h, 2);
    }
    return out;
  }
  out.resize(linear.size());
  for (size_t i = 0; i < linear.size(); ++i) {
    double v = linear[i];
    if (format == VK_FORMAT_R8G8B8A8_SRGB && i % 4 != 3) v = linear_to_srgb(std::clamp(v, 0.0, 1.0));
    out[i] = std::byte(uint8_t(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)));
  }
  return out;
}

// The image budget, with the side no wider than the device takes: a file
// past this device's maxImageDimension2D is refused from its header, before
// any decoding, with a message that names that limit.
ImageLimits texture_limits(const Context& context) {
  VkPhysicalDeviceProperties properties{};
  vkGetPhysicalDeviceProperties(context.physical_device(), &properties);
  ImageLimits limits;
  if (properties.limits.maxImageDimension2D < limits.max_side) {
    limits.max_side = properties.limits.maxImageDimension2D;
    limits.side_source = "this device's maxImageDimension2D";
  }
  return limits;
}

}  // namespace

Resources::~Resources() {
  if (sampler_) vkDestroySampler(context_.device(), sampler_, nullptr);
  if (point_sampler_) vkDestroySampler(context_.device(), point_sampler_, nullptr);
  if (clamp_sampler_) vkDestroySampler(context_.device(), clamp_sampler_, nullptr);
}

namespace {

Result<VkSampler, std::string> create_sampler(VkDevice device, const VkSamplerCreateInfo& info, VkSampler& kept) {
  if (kept) return kept;
  if (VkResult r = vkCreateSampler(device, &info, nullptr, &kept); r != VK_SUCCESS) {
    kept = VK_NULL_HANDLE;
    return unexpected(fmt::format("cannot create a sampler (VkResult {})", int(r)));
  }
  return kept;
}

}  // namespace

Result<VkSampler, std::string> Resources::point_sampler() {
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = info.minFilter = VK_FILTER_NEAREST;
  info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  info.addressModeU = info.addressModeV = info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  return create_sampler(context_.device(), info, point_sampler_);
}

Result<VkSampler, std::string> Resources::clamp_sampler() {
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = info.minFilter = VK_FILTER_LINEAR;
  info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  info.addressModeU = info.addressModeV = info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  return create_sampler(context_.device(), info, clamp_sampler_);
}

Result<VkSampler, std::string> Resources::sampler() {
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = VK_FILTER_LINEAR;
  info.minFilter = VK_FILTER_LINEAR;
  info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR;
  info.addressModeU = info.addressModeV = info.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
  info.maxLod = VK_LOD_CLAMP_NONE;
  return create_sampler(context_.device(), info, sampler_);
}

Result<LoadedTexture, std::string> Resources::solid(const std::array<float, 4>& rgba, VkImageViewType view,
                                                    uint32_t layers, bool srgb) {
  VkFormat format = srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R16G16B16A16_SFLOAT;
  VkResultOf<Image> image = create_image(context_, {.layers = layers, .format = format,
                                                    .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                                    .view = view});
  if (!image) return unexpected(describe(image.error()));
  std::vector<float> texels;
  for (uint32_t i = 0; i < layers; ++i) texels.insert(texels.end(), rgba.begin(), rgba.end());
  std::vector<std::byte> bytes = encode(texels, format);
  VkResultOf<void> up = upload_image(context_, *image, {std::span<const std::byte>(bytes)});
  if (!up) return unexpected(describe(up.error()));
  LoadedTexture made{std::move(*image), 1, 1};
  if (keep_pixels_) made.mips.push_back(std::move(bytes));
  return made;
}

Result<LoadedTexture, std::string> Resources::load_file(const SceneTexture& ref) {
  Result<DecodedImage, std::string> decoded = read_image_file(ref.name, texture_limits(context_));
  if (!decoded) return unexpected(fmt::format("{}: {}", ref.name, decoded.error()));
  uint32_t w = decoded->width, h = decoded->height;
  int channels = decoded->channels;
  bool hdr = decoded->floating;
  const std::vector<float>& raw = decoded->pixels;
  // RGBA, rows flipped: uv (0, 0) is the image's bottom-left corner, as in Unity.
  std::vector<float> linear(size_t(w) * h * 4);
  bool decode = ref.srgb && !hdr;
  for (uint32_t y = 0; y < h; ++y) {
    for (uint32_t x = 0; x < w; ++x) {
      const float* s = &raw[(size_t(h - 1 - y) * w + x) * channels];
      float* d = &linear[(size_t(y) * w + x) * 4];
      float rgba[4] = {s[0], channels > 1 && channels != 2 ? s[1] : s[0], channels > 2 ? s[2] : s[0],
                       channels == 4 ? s[3] : channels == 2 ? s[1] : 1.0f};
      if (ref.alpha_from_gray && (channels == 1 || channels == 3)) {
        rgba[3] = 0.2126f * rgba[0] + 0.7152f * rgba[1] + 0.0722f * rgba[2];
      }
      if (const auto& factors = ref.gltf_metallic_roughness) {  // glTF: roughness in G, metallic in B
        float metallic = (*factors)[0] * rgba[2], smoothness = 1 - (*factors)[1] * rgba[1];
        rgba[0] = metallic;
        rgba[1] = rgba[2] = 0;
        rgba[3] = smoothness;
      }
      for (int c = 0; c < 4; ++c) d[c] = decode && c < 3 ? float(srgb_to_linear(rgba[c])) : rgba[c];
    }
  }
  VkFormat format = hdr ? VK_FORMAT_R16G16B16A16_SFLOAT : ref.srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM;
  std::vector<std::vector<std::byte>> mips;
  uint32_t mw = w, mh = h;
  std::vector<float> level = linear;
  while (true) {
    mips.push_back(encode(level, format));
    if (mw == 1 && mh == 1) break;
    uint32_t nw, nh;
    level = downsample(level, mw, mh, nw, nh);
    mw = nw;
    mh = nh;
  }
  VkResultOf<Image> image = create_image(context_, {.width = w, .height = h, .mips = uint32_t(mips.size()),
                                                    .format = format,
                                                    .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT});
  if (!image) return unexpected(fmt::format("{}: {}", ref.name, describe(image.error())));
  std::vector<std::span<const std::byte>> spans(mips.begin(), mips.end());
  VkResultOf<void> up = upload_image(context_, *image, spans);
  if (!up) return unexpected(describe(up.error()));
  ++files_loaded_;
  LoadedTexture made{std::move(*image), w, h};
  if (keep_pixels_) made.mips = std::move(mips);
  return made;
}

Result<const LoadedTexture*, std::string> Resources::texture(const SceneTexture& ref) {
  auto key = std::make_tuple(ref.name, ref.srgb, ref.alpha_from_gray, ref.gltf_metallic_roughness);
  if (auto it = textures_.find(key); it != textures_.end()) return it->second.get();
  Result<LoadedTexture, std::string> made =
      ref.builtin ? solid(builtin_rgba(ref.name), VK_IMAGE_VIEW_TYPE_2D, 1, false) : load_file(ref);
  if (!made) return unexpected(made.error());
  auto& slot = textures_[key];
  slot = std::make_unique<LoadedTexture>(std::move(*made));
  return slot.get();
}

Result<const Image*, std::string> Resources::fallback(std::string_view dim, bool arrayed) {
  if (dim == "Cube" && !arrayed && environment_) return &environment_->image;
  std::string key = std::string(dim) + (arrayed ? "[]" : "");
  if (auto it = fallbacks_.find(key); it != fallbacks_.end()) return &it->second->image;
  VkImageViewType view = VK_IMAGE_VIEW_TYPE_2D;
  uint32_t layers = 1;
  if (dim == "Cube") {
    view = arrayed ? VK_IMAGE_VIEW_TYPE_CUBE_ARRAY : VK_IMAGE_VIEW_TYPE_CUBE;
    layers = 6;
  } else if (dim == "3D") {
    view = VK_IMAGE_VIEW_TYPE_3D;
  } else if (dim == "1D") {
    view = arrayed ? VK_IMAGE_VIEW_TYPE_1D_ARRAY : VK_IMAGE_VIEW_TYPE_1D;
  } else if (arrayed) {
    view = VK_IMAGE_VIEW_TYPE_2D_ARRAY;
  }
  if (view == VK_IMAGE_VIEW_TYPE_1D || view == VK_IMAGE_VIEW_TYPE_1D_ARRAY) {
    return unexpected(std::string("1D textures are not supported"));
  }
  Result<LoadedTexture, std::string> made = solid({1, 1, 1, 1}, view, layers, false);
  if (!made) return unexpected(made.error());
  auto& slot = fallbacks_[key];
  slot = std::make_unique<LoadedTexture>(std::move(*made));
  return &slot->image;
}

const std::vector<std::vector<std::byte>>* Resources::pixels_of(const Image* image) const {
  auto kept = [&](const LoadedTexture* t) { return t && &t->image == image && !t->mips.empty(); };
  for (const auto& [key, t] : textures_)
    if (kept(t.get())) return &t->mips;
  for (const auto& [key, t] : fallbacks_)
    if (kept(t.get())) return &t->mips;
  if (kept(environment_.get())) return &environment_->mips;
  for (const auto& t : probes_)
    if (kept(t.get())) return &t->mips;
  for (const auto& [key, t] : light_textures_)
    if (kept(t.get())) return &t->mips;
  return nullptr;
}

Result<const Image*, std::string> Resources::made_texture(std::pair<float, float> key, uint32_t width, uint32_t height,
                                                          const std::function<float(float, float)>& value) {
  if (auto it = light_textures_.find(key); it != light_textures_.end()) return &it->second->image;
  std::vector<float> texels;
  for (uint32_t y = 0; y < height; ++y) {
    for (uint32_t x = 0; x < width; ++x) {
      float v = value((float(x) + 0.5f) / float(width), (float(y) + 0.5f) / float(height));
      texels.insert(texels.end(), {v, v, v, v});  // UNITY_ATTEN_CHANNEL may be r or a
    }
  }
  const VkFormat format = VK_FORMAT_R16G16B16A16_SFLOAT;
  VkResultOf<Image> image = create_image(context_, {.width = width, .height = height, .format = format,
                                                    .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT});
  if (!image) return unexpected(describe(image.error()));
  std::vector<std::byte> bytes = encode(texels, format);
  VkResultOf<void> up = upload_image(context_, *image, {std::span<const std::byte>(bytes)});
  if (!up) return unexpected(describe(up.error()));
  auto& slot = light_textures_[key];
  slot = std::make_unique<LoadedTexture>(LoadedTexture{std::move(*image), width, height});
  if (keep_pixels_) slot->mips.push_back(std::move(bytes));
  return &slot->image;
}

Result<const Image*, std::string> Resources::light_falloff() {
  // FacetDistanceAttenuation at d^2 = u: (1 - u^2)^2 / (1 + 25 u), 0 from the range on.
  return made_texture({0.0f, 0.0f}, 256, 1, [](float u, float) {
    float window = std::clamp(1.0f - u * u, 0.0f, 1.0f);
    return window * window / (1.0f + 25.0f * u);
  });
}

Result<const Image*, std::string> Resources::spot_cone(float cos_outer, float cos_inner) {
  // uv - 0.5 = (x, y) / (z 2 tan(outer)): the off-axis tangent is 2 |uv - 0.5| tan(outer).
  const float tan_outer = std::sqrt(std::max(0.0f, 1.0f - cos_outer * cos_outer)) / std::max(cos_outer, 1e-6f);
  return made_texture({cos_outer, cos_inner}, 64, 64, [=](float u, float v) {
    float r = 2.0f * std::hypot(u - 0.5f, v - 0.5f) * tan_outer;
    float cos_angle = 1.0f / std::sqrt(1.0f + r * r);
    float t = std::clamp((cos_angle - cos_outer) / std::max(cos_inner - cos_outer, 1e-4f), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
  });
}

bool Resources::clamped(const Image* image) const {
  for (const auto& [key, t] : light_textures_)
    if (&t->image == image) return true;
  return false;
}

Result<void, std::string> Resources::load_cookies(const Scene& scene) {
  for (const SceneLight& light : scene.lights) {
    if (!light.cookie) continue;
    Result<const LoadedTexture*, std::string> t = texture(*light.cookie);
    if (!t) return unexpected(fmt::format("{}: {}.cookie: {}", scene.path, light.json_path, t.error()));
  }
  return {};
}

namespace {

Result<LoadedTexture, std::string> upload_cube(const Context& context, const CubeMips& cube, bool keep_pixels) {
  std::vector<std::vector<std::byte>> mips;
  for (const std::vector<float>& level : cube.mips) mips.push_back(encode(level, VK_FORMAT_R16G16B16A16_SFLOAT));
  VkResultOf<Image> image = create_image(context, {.width = cube.size, .height = cube.size, .layers = 6,
                                                   .mips = uint32_t(mips.size()), .format = VK_FORMAT_R16G16B16A16_SFLOAT,
                                                   .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                                                   .view = VK_IMAGE_VIEW_TYPE_CUBE});
  if (!image) return unexpected(describe(image.error()));
  std::vector<std::span<const std::byte>> spans(mips.begin(), mips.end());
  VkResultOf<void> up = upload_image(context, *image, spans);
  if (!up) return unexpected(describe(up.error()));
  LoadedTexture made{std::move(*image), cube.size, cube.size};
  if (keep_pixels) made.mips = std::move(mips);
  return made;
}

}  // namespace

Result<const Image*, std::string> Resources::environment_cube(const CubeMips& cube) {
  Result<LoadedTexture, std::string> made = upload_cube(context_, cube, keep_pixels_);
  if (!made) return unexpected(made.error());
  environment_ = std::make_unique<LoadedTexture>(std::move(*made));
  return &environment_->image;
}

Result<const Image*, std::string> Resources::add_probe(const CubeMips& cube) {
  Result<LoadedTexture, std::string> made = upload_cube(context_, cube, keep_pixels_);
  if (!made) return unexpected(made.error());
  probes_.push_back(std::make_unique<LoadedTexture>(std::move(*made)));
  return &probes_.back()->image;
}

}  // namespace facet::runtime
