// PNG and EXR files through image_io, written atomically, and the --explain listing.
#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <tuple>

#include "facet/runtime/renderer.h"
#include "facet/support/atomic_file.h"
#include "facet/support/text.h"
#include "image_io/image_io.h"

namespace facet::runtime {
namespace {

template <typename Pixel>
Result<void> write_atomically(const std::string& path, const RenderedFrame& frame, const Pixel* pixels,
                              Diagnostics& diags) {
  Result<void, std::string> written = support::replace_file_atomically(path, [&](const std::string& temporary) {
    return write_image_file(temporary, frame.width, frame.height, pixels);
  });
  if (written) return {};
  diags.add(DiagId::output_unwritable, SourceSpan{},
            fmt::format("{}: cannot write the image: {}", path, written.error()));
  return failure();
}

std::string join(const std::vector<std::string>& words) {
  std::string s;
  for (const std::string& w : words) s += (s.empty() ? "" : " ") + w;
  return s.empty() ? "(none)" : s;
}

}  // namespace

Result<void> write_png(const RenderedFrame& frame, const std::string& path, Diagnostics& diags) {
  return write_atomically(path, frame, frame.ldr.data(), diags);
}

Result<void> write_exr(const RenderedFrame& frame, const std::string& path, Diagnostics& diags) {
  return write_atomically(path, frame, frame.hdr.data(), diags);
}

// --explain names each pass of each object once: its draws (numbered in
// submission order, so the order stays visible) under one line, and a pass
// that was never drawn once, with every reason it was skipped.
std::string explain_text(const RenderedFrame& frame) {
  using PassKey = std::tuple<std::string, std::string, std::string>;  // object, shader, pass
  auto key_of = [](const DrawRecord& d) { return PassKey{d.object, d.shader, d.pass}; };
  std::vector<PassKey> drawn_order, skipped_order;
  std::map<PassKey, std::vector<std::pair<size_t, const DrawRecord*>>> draws;
  std::map<PassKey, std::vector<std::string>> skipped_why;
  std::map<PassKey, const DrawRecord*> first_skipped;
  size_t n = 0;
  for (const DrawRecord& d : frame.draws) {
    PassKey key = key_of(d);
    if (d.drawn) {
      auto& list = draws[key];
      if (list.empty()) drawn_order.push_back(key);
      list.emplace_back(++n, &d);
      continue;
    }
    auto& whys = skipped_why[key];
    if (whys.empty()) {
      skipped_order.push_back(key);
      first_skipped[key] = &d;
    }
    if (std::find(whys.begin(), whys.end(), d.why) == whys.end()) whys.push_back(d.why);
  }
  std::string text;
  for (const PassKey& key : drawn_order) {
    const auto& list = draws[key];
    const DrawRecord& first = *list.front().second;
    std::string mode = first.light_mode.empty() ? "no LightMode" : first.light_mode;
    text += fmt::format("{} '{}' pass {} ({}), queue {}: {}\n", first.object, first.shader, first.pass, mode,
                        first.queue, count_of(list.size(), "draw", "draws"));
    for (const auto& [number, d] : list) {
      text += fmt::format("{:4} {}\n       variant: {}{}\n       state: {}\n       why: {}\n", number,
                          d->light.empty() ? "without a light" : "light " + d->light, join(d->keywords),
                          d->exact ? "" : " (closest match)", d->state, d->why);
    }
  }
  bool heading = false;
  for (const PassKey& key : skipped_order) {
    if (draws.count(key)) continue;  // drawn elsewhere (a ShadowCaster into a shadow map)
    if (!heading) text += "not drawn:\n";
    heading = true;
    const auto& [object, shader, pass] = key;
    const DrawRecord* first = first_skipped[key];
    std::string mode = first->light_mode.empty() ? "no LightMode" : first->light_mode;
    std::string whys;
    for (const std::string& w : skipped_why[key]) whys += (whys.empty() ? "" : "; ") + w;
    text += fmt::format("   - {} '{}' pass {} ({}): {}\n", object, shader, pass, mode, whys);
  }
  return text;
}

}  // namespace facet::runtime
