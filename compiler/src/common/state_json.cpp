#include "facet/support/state_json.h"

namespace facet {
namespace {

using Json = nlohmann::ordered_json;

void put(Json& out, const char* key, const std::optional<ir::StateValue>& v) {
  if (v) out[key] = state_value_json(*v);
}

Json stencil(const ir::StencilState& s) {
  Json out = Json::object();
  put(out, "ref", s.ref);
  put(out, "read_mask", s.read_mask);
  put(out, "write_mask", s.write_mask);
  put(out, "comp", s.comp);
  put(out, "pass", s.pass);
  put(out, "fail", s.fail);
  put(out, "zfail", s.zfail);
  put(out, "comp_back", s.comp_back);
  put(out, "pass_back", s.pass_back);
  put(out, "fail_back", s.fail_back);
  put(out, "zfail_back", s.zfail_back);
  put(out, "comp_front", s.comp_front);
  put(out, "pass_front", s.pass_front);
  put(out, "fail_front", s.fail_front);
  put(out, "zfail_front", s.zfail_front);
  return out;
}

Json render_targets(const ir::RenderState& s, Json out) {
  if (!s.blend.empty()) {
    Json& list = out["blend"] = Json::array();
    for (const ir::BlendState& b : s.blend) {
      Json j{{"target", b.render_target}, {"off", b.off}, {"src", state_value_json(b.src)}, {"dst", state_value_json(b.dst)}};
      put(j, "src_alpha", b.src_alpha);
      put(j, "dst_alpha", b.dst_alpha);
      list.push_back(std::move(j));
    }
  }
  if (!s.blend_op.empty()) {
    Json& list = out["blend_op"] = Json::array();
    for (const ir::BlendOpState& b : s.blend_op) {
      Json j{{"target", b.render_target}, {"color_op", state_value_json(b.color_op)}};
      put(j, "alpha_op", b.alpha_op);
      list.push_back(std::move(j));
    }
  }
  if (!s.color_mask.empty()) {
    Json& list = out["color_mask"] = Json::array();
    for (const ir::ColorMaskState& c : s.color_mask) {
      list.push_back(Json{{"target", c.render_target}, {"mask", state_value_json(c.mask)}});
    }
  }
  return out;
}

}  // namespace

Json tags_json(const std::vector<ir::Tag>& tags) {
  Json out = Json::array();
  for (const ir::Tag& t : tags) out.push_back(Json::array({t.key, t.value}));
  return out;
}

// A literal prints as its text, a property reference as {"property": name}.
Json state_value_json(const ir::StateValue& v) {
  if (v.is_property()) return Json{{"property", v.property}};
  return v.literal;
}

Json render_state_json(const ir::RenderState& s) {
  Json out = Json::object();
  put(out, "cull", s.cull);
  put(out, "ztest", s.ztest);
  put(out, "zwrite", s.zwrite);
  put(out, "alpha_to_mask", s.alpha_to_mask);
  put(out, "zclip", s.zclip);
  put(out, "conservative", s.conservative);
  put(out, "offset_factor", s.offset_factor);
  put(out, "offset_units", s.offset_units);
  out = render_targets(s, std::move(out));
  if (s.stencil) out["stencil"] = stencil(*s.stencil);
  return out;
}

}  // namespace facet
