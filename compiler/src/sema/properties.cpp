// Properties: the type name (case-insensitive), its arguments, the default
// value's form, and unique names.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <unordered_map>

#include "facet/support/suggest.h"
#include "lower.h"

namespace facet::sema {
namespace {

struct TypeName {
  std::string_view name;
  ir::PropertyType type;
};

constexpr std::array<TypeName, 12> kTypes = {{
    {"Float", ir::PropertyType::float_},
    {"Int", ir::PropertyType::int_},
    {"Integer", ir::PropertyType::integer},
    {"Range", ir::PropertyType::range},
    {"Color", ir::PropertyType::color},
    {"Vector", ir::PropertyType::vector},
    {"2D", ir::PropertyType::tex2d},
    {"3D", ir::PropertyType::tex3d},
    {"Cube", ir::PropertyType::cube},
    {"2DArray", ir::PropertyType::tex2d_array},
    {"CubeArray", ir::PropertyType::cube_array},
    {"Any", ir::PropertyType::tex_any},
}};

// Unity's legacy spellings, accepted as they are in Unity 2017-2019.
constexpr std::array<TypeName, 1> kLegacyTypes = {{
    {"RECT", ir::PropertyType::tex2d},  // the old rectangle texture: a 2D texture
}};

constexpr std::array<std::string_view, 12> kTypeNames = {
    "Float", "Int", "Integer", "Range", "Color", "Vector", "2D", "3D", "Cube", "2DArray", "CubeArray", "Any"};

constexpr std::array<std::string_view, 8> kTextureDefaults = {
    "white", "black", "gray", "grey", "bump", "red", "linearGray", ""};

std::optional<ir::PropertyType> lookup_type(const ast::Property& p, Context& ctx) {
  for (const TypeName& t : kTypes) {
    if (iequals(t.name, p.type)) return t.type;
  }
  for (const TypeName& t : kLegacyTypes) {
    if (iequals(t.name, p.type)) return t.type;
  }
  Diagnostic& d = ctx.error(DiagId::sema_unknown_property_type, p.type_span,
                            "unknown property type '" + p.type + "'");
  if (auto best = suggest(p.type, kTypeNames)) {
    d.note(p.type_span, "did you mean '" + std::string(*best) + "'?");
    SourceSpan word{p.type_span.file, p.type_span.begin, uint32_t(p.type_span.begin + p.type.size())};
    d.fix(word, std::string(*best));
  } else {
    d.note({}, "valid types are " + join(kTypeNames));
  }
  return std::nullopt;
}

bool check_type_args(const ast::Property& p, ir::PropertyType type, ir::Property& out, Context& ctx) {
  if (type == ir::PropertyType::range) {
    if (p.type_args.size() != 2) {
      ctx.error(DiagId::sema_bad_property_type, p.type_span, "'Range' needs two numbers, as in 'Range(0, 1)'");
      return false;
    }
    out.range_min = float(p.type_args[0]);
    out.range_max = float(p.type_args[1]);
    if (out.range_min > out.range_max) {
      ctx.report(DiagId::sema_bad_property_range, p.type_span,
                 "the minimum of range property '" + p.name + "' is greater than its maximum");
    }
    return true;
  }
  if (p.type_has_parens) {
    ctx.error(DiagId::sema_bad_property_type, p.type_span, "property type '" + p.type + "' takes no arguments");
    return false;
  }
  return true;
}

std::string type_word(ir::PropertyType t) { return std::string(ir::property_type_name(t)); }

bool check_default(const ast::Property& p, ir::PropertyType type, ir::Property& out, Context& ctx) {
  const ast::PropertyDefault& d = p.default_value;
  using Kind = ast::PropertyDefault::Kind;
  auto fail = [&](std::string expected) {
    ctx.error(DiagId::sema_bad_property_default, d.span,
              type_word(type) + " property '" + p.name + "' needs " + expected + " as its default");
    return false;
  };
  switch (type) {
    case ir::PropertyType::float_:
    case ir::PropertyType::int_:
    case ir::PropertyType::integer:
    case ir::PropertyType::range:
      if (d.kind != Kind::number || d.numbers.empty()) return fail("a number");
      out.default_value[0] = float(d.numbers[0]);
      return true;
    case ir::PropertyType::color:
    case ir::PropertyType::vector: {
      size_t min = type == ir::PropertyType::color ? 3 : 2;
      if (d.kind != Kind::vector || d.numbers.size() < min || d.numbers.size() > 4) {
        return fail(type == ir::PropertyType::color ? "'(r, g, b)' or '(r, g, b, a)'" : "'(x, y, z, w)'");
      }
      for (size_t i = 0; i < d.numbers.size(); ++i) out.default_value[i] = float(d.numbers[i]);
      // A 3-number colour is opaque.
      if (type == ir::PropertyType::color && d.numbers.size() == 3) out.default_value[3] = 1;
      return true;
    }
    default: break;
  }
  if (d.kind != Kind::texture) return fail("a texture name such as '\"white\" {}'");
  out.default_texture = d.texture;
  bool known = false;
  for (std::string_view name : kTextureDefaults) known = known || iequals(name, d.texture);
  if (!known) {
    Diagnostic& w = ctx.report(DiagId::sema_unknown_texture_default, d.span,
                               "unknown default texture '" + d.texture + "'; it reads as gray");
    if (auto best = suggest(d.texture, kTextureDefaults)) w.note(d.span, "did you mean '" + std::string(*best) + "'?");
    else w.note({}, "built-in textures are white, black, gray, grey, bump, red, linearGray");
  }
  return true;
}

}  // namespace

std::vector<ir::Property> lower_properties(const std::vector<ast::Property>& properties, Context& ctx) {
  std::vector<ir::Property> out;
  std::unordered_map<std::string, const ast::Property*> seen;
  for (const ast::Property& p : properties) {
    auto [first, inserted] = seen.emplace(p.name, &p);
    if (!inserted) {
      // Unity lists both, and its lookups by name find the first; facet
      // keeps the first.
      ctx.report(DiagId::sema_duplicate_property, p.name_span,
                 "property '" + p.name + "' is declared twice; the first declaration is used")
          .note(first->second->name_span, "'" + p.name + "' was first declared here");
      continue;
    }
    ir::Property prop{.name = p.name, .display_name = p.display_name, .span = p.span};
    for (const ast::Attribute& a : p.attributes) {
      ir::PropertyAttribute& attribute = prop.attributes.emplace_back();
      attribute.name = a.name;
      attribute.args = a.args;
      attribute.span = a.span;
    }
    auto type = lookup_type(p, ctx);
    if (!type) continue;
    prop.type = *type;
    bool ok = check_type_args(p, *type, prop, ctx);
    ok = check_default(p, *type, prop, ctx) && ok;
    if (ok) out.push_back(std::move(prop));
  }
  return out;
}

}  // namespace facet::sema

namespace facet::sema {

void check_property_reference(std::string_view name, SourceSpan span, Context& ctx) {
  const std::vector<std::string>& names = ctx.property_names;
  if (std::find(names.begin(), names.end(), name) != names.end()) return;
  std::vector<std::string_view> candidates(names.begin(), names.end());
  // A typo is an edit or two; a looser match would flag the globals.
  auto best = suggest(name, candidates);
  if (!best || edit_distance(name, *best) > std::max<size_t>(1, name.size() / 5)) return;
  // The span of "[_Prop]" narrowed to the name, which the fix replaces.
  const std::string& text = ctx.sources.text(span.file);
  if (span.end > span.begin + 1 && span.end <= text.size() && text[span.begin] == '[' && text[span.end - 1] == ']') {
    span = {span.file, span.begin + 1, span.end - 1};
  }
  ctx.report(DiagId::sema_unknown_property_reference, span,
             fmt::format("'{}' is not a declared property; did you mean '{}'?", name, *best))
      .fix(span, std::string(*best));
}

}  // namespace facet::sema
