// PNG and EXR files through image_io, written atomically, and the --explain listing.
#include <fmt/format.h>
#include <unistd.h>

#include <filesystem>

#include "facet/runtime/renderer.h"
#include "image_io/image_io.h"

namespace facet::runtime {
namespace {

// The writer picks the format by extension, so the temporary file keeps it.
template <typename Pixel>
Result<void, RenderError> write_atomically(const std::string& path, const RenderedFrame& frame, const Pixel* pixels) {
  std::filesystem::path target(path);
  std::filesystem::path temp = target.parent_path() /
                               fmt::format(".{}.tmp{}{}", target.stem().string(), getpid(), target.extension().string());
  if (Result<void, std::string> written = write_image_file(temp.string(), frame.width, frame.height, pixels); !written) {
    std::error_code ec;
    std::filesystem::remove(temp, ec);
    return unexpected(RenderError{fmt::format("{}: cannot write the image: {}", path, written.error())});
  }
  std::error_code ec;
  std::filesystem::rename(temp, target, ec);
  if (ec) {
    std::filesystem::remove(temp, ec);
    return unexpected(RenderError{fmt::format("{}: cannot write the image: {}", path, ec.message())});
  }
  return {};
}

std::string join(const std::vector<std::string>& words) {
  std::string s;
  for (const std::string& w : words) s += (s.empty() ? "" : " ") + w;
  return s.empty() ? "(none)" : s;
}

}  // namespace

Result<void, RenderError> write_png(const RenderedFrame& frame, const std::string& path) {
  return write_atomically(path, frame, frame.ldr.data());
}

Result<void, RenderError> write_exr(const RenderedFrame& frame, const std::string& path) {
  return write_atomically(path, frame, frame.hdr.data());
}

std::string explain_text(const RenderedFrame& frame) {
  std::string text;
  size_t n = 0;
  for (const DrawRecord& d : frame.draws) {
    std::string mode = d.light_mode.empty() ? "no LightMode" : d.light_mode;
    if (!d.drawn) {
      text += fmt::format("   - {} '{}' pass {} ({}): not drawn: {}\n", d.object, d.shader, d.pass, mode, d.why);
      continue;
    }
    text += fmt::format("{:4} {} '{}' pass {} ({}), queue {}{}\n", ++n, d.object, d.shader, d.pass, mode, d.queue,
                        d.light.empty() ? "" : ", light " + d.light);
    text += fmt::format("       variant: {}{}\n       state: {}\n       why: {}\n", join(d.keywords),
                        d.exact ? "" : " (closest match)", d.state, d.why);
  }
  return text;
}

}  // namespace facet::runtime
