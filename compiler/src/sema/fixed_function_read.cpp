// Legacy commands -> FixedFunctionState. The block bodies (Material,
// SetTexture, Fog, BindChannels) come as the parser's tokens; each has a
// small grammar of its own, read here with one token of lookahead. A
// malformed command is one located error and leaves the state as it was.
#include <algorithm>

#include "fixed_function.h"

namespace facet::sema {
namespace {

using Token = ast::LegacyToken;

class Reader {
 public:
  Reader(const ast::LegacyCommand& c, Context& ctx) : c_(c), ctx_(ctx) {}

  bool done() const { return pos_ >= c_.body.size(); }
  const Token* peek() const { return done() ? nullptr : &c_.body[pos_]; }
  const Token& take() { return c_.body[pos_++]; }
  bool at_word(std::string_view w) const { return peek() && peek()->kind == Token::Kind::word && iequals(peek()->text, w); }
  bool at_symbol(std::string_view s) const { return peek() && peek()->kind == Token::Kind::symbol && peek()->text == s; }

  // Where the next token is, or the closing brace when there is none.
  SourceSpan here() const {
    if (const Token* t = peek()) return t->span;
    SourceSpan end = c_.body_span;
    if (end.end > end.begin) end.begin = end.end - 1;
    return end;
  }
  std::string describe() const { return done() ? "'}'" : "'" + peek()->text + "'"; }

  bool fail(SourceSpan span, std::string message) {
    ctx_.error(DiagId::sema_bad_legacy_command, span, std::move(message));
    return false;
  }
  bool expected(std::string_view what, std::string_view context) {
    return fail(here(), "expected " + std::string(what) + " " + std::string(context) + ", not " + describe());
  }

  bool expect_symbol(std::string_view s, std::string_view context) {
    if (at_symbol(s)) {
      take();
      return true;
    }
    return expected("'" + std::string(s) + "'", context);
  }

  // "(r, g, b[, a])" or "[_Prop]"; a number alone is accepted for scalars.
  // A colour's component may itself be a float property: "(1, 1, 1, [_A])".
  bool value(FfValue& out, bool color, std::string_view context) {
    if (peek() && peek()->kind == Token::Kind::property) {
      const Token& t = take();
      out = {};
      out.property = t.text;
      out.span = t.span;
      check_property_reference(t.text, t.span, ctx_);
      return true;
    }
    if (!color) {
      if (!peek() || peek()->kind != Token::Kind::number) return expected("a number or '[_Prop]'", context);
      const Token& t = take();
      out = {};
      out.literal[0] = float(t.number);
      out.span = t.span;
      return true;
    }
    if (!at_symbol("(")) return expected("a colour '(r, g, b, a)' or '[_Prop]'", context);
    SourceSpan open = take().span;
    std::vector<float> numbers;
    std::array<std::string, 4> properties;
    while (peek() && (peek()->kind == Token::Kind::number || peek()->kind == Token::Kind::property)) {
      const Token& t = take();
      if (t.kind == Token::Kind::property && numbers.size() < properties.size()) properties[numbers.size()] = t.text;
      if (t.kind == Token::Kind::property) check_property_reference(t.text, t.span, ctx_);
      numbers.push_back(t.kind == Token::Kind::number ? float(t.number) : 0.0f);
      if (!at_symbol(",")) break;
      take();
    }
    if (!expect_symbol(")", context)) return false;
    SourceSpan span{open.file, open.begin, c_.body[pos_ - 1].span.end};
    if (!set_color(out, numbers, span)) return false;
    out.component_properties = properties;
    return true;
  }

  bool set_color(FfValue& out, const std::vector<float>& numbers, SourceSpan span) {
    if (numbers.size() != 3 && numbers.size() != 4) {
      return fail(span, "a colour has 3 or 4 numbers, not " + std::to_string(numbers.size()));
    }
    out = {};
    out.literal = {numbers[0], numbers[1], numbers[2], numbers.size() == 4 ? numbers[3] : 1.0f};
    out.span = span;
    return true;
  }

 private:
  const ast::LegacyCommand& c_;
  Context& ctx_;
  size_t pos_ = 0;
};

bool on_off(const ast::LegacyCommand& c, bool& out, Context& ctx) {
  if (!c.values.empty() && c.values[0].kind == ast::Value::Kind::word) {
    if (iequals(c.values[0].text, "On")) return out = true, true;
    if (iequals(c.values[0].text, "Off")) return out = false, true;
  }
  SourceSpan at = c.values.empty() ? c.keyword_span : c.values[0].span;
  ctx.error(DiagId::sema_bad_legacy_command, at, "expected 'On' or 'Off' after '" + c.name + "'");
  return false;
}

bool read_material(Reader& r, FixedFunctionState& state) {
  static constexpr std::string_view kFields[] = {"Diffuse", "Ambient", "Specular", "Shininess", "Emission"};
  FixedFunctionState m = state;
  m.diffuse = m.ambient = m.specular = m.emission = m.shininess = {};
  while (!r.done()) {
    const Token& field = *r.peek();
    FfValue* target = nullptr;
    if (iequals(field.text, "Diffuse")) target = &m.diffuse;
    else if (iequals(field.text, "Ambient")) target = &m.ambient;
    else if (iequals(field.text, "Specular")) target = &m.specular;
    else if (iequals(field.text, "Emission")) target = &m.emission;
    else if (iequals(field.text, "Shininess")) target = &m.shininess;
    if (field.kind != Token::Kind::word || !target) {
      std::string message = "unknown Material field '" + field.text + "'";
      if (auto s = suggest(field.text, kFields)) message += "; did you mean '" + std::string(*s) + "'?";
      return r.fail(field.span, message + " (expected Diffuse, Ambient, Specular, Shininess or Emission)");
    }
    r.take();
    bool is_color = target != &m.shininess;
    if (!r.value(*target, is_color, "after '" + field.text + "'")) return false;
  }
  state.diffuse = m.diffuse;
  state.ambient = m.ambient;
  state.specular = m.specular;
  state.emission = m.emission;
  state.shininess = m.shininess;
  return true;
}

bool read_operand(Reader& r, FfOperand& out) {
  out = {};
  if (r.at_word("one")) {
    r.take();
    if (!r.expect_symbol("-", "after 'one' (as in 'one - texture')")) return false;
    out.one_minus = true;
  }
  static constexpr std::pair<std::string_view, FfSource> kSources[] = {
      {"previous", FfSource::previous}, {"primary", FfSource::primary},
      {"texture", FfSource::texture}, {"constant", FfSource::constant}};
  const Token* t = r.peek();
  bool found = false;
  for (auto [word, source] : kSources) {
    if (r.at_word(word)) {
      out.source = source;
      found = true;
    }
  }
  if (!found) {
    if (t && t->kind == Token::Kind::word) {
      return r.fail(t->span, "unknown combiner source '" + t->text +
                                 "' (expected previous, primary, texture or constant)");
    }
    return r.expected("a combiner source (previous, primary, texture or constant)", "in 'combine'");
  }
  r.take();
  if (r.at_word("alpha")) {
    r.take();
    out.alpha = true;
  }
  return true;
}

bool read_combine_expr(Reader& r, FfCombine& out) {
  out = {};
  if (!read_operand(r, out.args[0])) return false;
  if (r.at_word("lerp")) {
    r.take();
    out.op = FfOp::lerp;
    return r.expect_symbol("(", "after 'lerp'") && read_operand(r, out.args[1]) &&
           r.expect_symbol(")", "after the lerp factor") && read_operand(r, out.args[2]);
  }
  if (r.at_symbol("*")) {
    r.take();
    out.op = FfOp::mul;
    if (!read_operand(r, out.args[1])) return false;
    if (r.at_symbol("+")) {
      r.take();
      out.op = FfOp::mul_add;
      if (r.at_symbol("-")) {
        r.take();
        out.op = FfOp::mul_add_signed;
      }
    } else if (r.at_symbol("-")) {
      r.take();
      out.op = FfOp::mul_sub;
    } else {
      return true;
    }
    return read_operand(r, out.args[2]);
  }
  if (r.at_symbol("+")) {
    r.take();
    out.op = FfOp::add;
    if (r.at_symbol("-")) {
      r.take();
      out.op = FfOp::add_signed;
    }
    return read_operand(r, out.args[1]);
  }
  if (r.at_symbol("-")) {
    r.take();
    out.op = FfOp::sub;
    return read_operand(r, out.args[1]);
  }
  return true;
}

void read_scale(Reader& r, FfCombine& c) {
  if (r.at_word("Double")) c.scale = 2;
  else if (r.at_word("Quad")) c.scale = 4;
  else return;
  r.take();
}

bool read_set_texture(const ast::LegacyCommand& c, Reader& r, FfStage& stage) {
  if (c.values.empty() || c.values[0].kind != ast::Value::Kind::property) {
    SourceSpan at = c.values.empty() ? c.keyword_span : c.values[0].span;
    return r.fail(at, "expected a texture property '[_MainTex]' after 'SetTexture'");
  }
  stage.texture = c.values[0].text;
  stage.span = c.span;
  bool has_combine = false;
  while (!r.done()) {
    const Token& field = *r.peek();
    if (field.kind == Token::Kind::word && iequals(field.text, "combine")) {
      r.take();
      if (!read_combine_expr(r, stage.color)) return false;
      read_scale(r, stage.color);
      stage.alpha = stage.color;
      if (r.at_symbol(",")) {
        r.take();
        if (!read_combine_expr(r, stage.alpha)) return false;
        read_scale(r, stage.alpha);
      }
      has_combine = true;
    } else if (field.kind == Token::Kind::word && iequals(field.text, "constantColor")) {
      r.take();
      if (!r.value(stage.constant, true, "after 'constantColor'")) return false;
      stage.has_constant = true;
    } else if (field.kind == Token::Kind::word && iequals(field.text, "matrix")) {
      r.take();
      if (!r.peek() || r.peek()->kind != Token::Kind::property) {
        return r.expected("a matrix property '[_Prop]'", "after 'matrix'");
      }
      stage.matrix = r.take().text;
    } else {
      return r.fail(field.span, "unknown SetTexture field '" + field.text +
                                    "' (expected combine, constantColor or matrix)");
    }
  }
  // "SetTexture [_T] {}" keeps Unity's default: the texture times the previous stage.
  if (!has_combine) {
    stage.color = {FfOp::mul, {FfOperand{FfSource::texture}, FfOperand{FfSource::previous}, {}}, 1};
    stage.alpha = stage.color;
  }
  return true;
}

bool read_fog(Reader& r, FixedFunctionState& state, Context& ctx) {
  static constexpr std::pair<std::string_view, FfFog> kModes[] = {
      {"Off", FfFog::off}, {"Global", FfFog::global}, {"Linear", FfFog::linear}, {"Exp", FfFog::exp},
      {"Exp2", FfFog::exp2}};
  FixedFunctionState f = state;
  while (!r.done()) {
    const Token& field = *r.peek();
    if (field.kind == Token::Kind::word && iequals(field.text, "Mode")) {
      r.take();
      bool found = false;
      for (auto [word, mode] : kModes) {
        if (r.at_word(word)) {
          f.fog = mode;
          found = true;
        }
      }
      if (!found) return r.expected("Off, Global, Linear, Exp or Exp2", "after 'Mode'");
      r.take();
    } else if (field.kind == Token::Kind::word && iequals(field.text, "Color")) {
      r.take();
      if (!r.value(f.fog_color, true, "after 'Color'")) return false;
      f.has_fog_color = true;
    } else if (field.kind == Token::Kind::word && (iequals(field.text, "Density") || iequals(field.text, "Range"))) {
      // Per-pass fog density and range: facet's fog comes from unity_FogParams.
      r.take();
      FfValue ignored;
      if (!r.value(ignored, false, "after '" + field.text + "'")) return false;
      if (r.at_symbol(",")) {
        r.take();
        if (!r.value(ignored, false, "after ','")) return false;
      }
      ctx.report(DiagId::sema_legacy_unsupported, field.span,
                 "'Fog { " + field.text + " }' is not supported; the global fog parameters are used");
    } else {
      return r.fail(field.span, "unknown Fog field '" + field.text + "' (expected Mode or Color)");
    }
  }
  state.fog = f.fog;
  state.has_fog_color = f.has_fog_color;
  state.fog_color = f.fog_color;
  return true;
}

// Bind "source", target: only the texture coordinates change what is generated.
bool read_bind_channels(Reader& r, FixedFunctionState& state) {
  std::array<int, 8> texcoord = state.stage_texcoord;
  while (!r.done()) {
    if (!r.at_word("Bind")) return r.expected("'Bind \"source\", target'", "in BindChannels");
    r.take();
    if (!r.peek() || r.peek()->kind != Token::Kind::string) return r.expected("a source channel string", "after 'Bind'");
    std::string source = r.take().text;
    if (!r.expect_symbol(",", "after the source channel")) return false;
    if (!r.peek() || r.peek()->kind != Token::Kind::word) return r.expected("a target channel", "after ','");
    const Token& target = r.take();
    int uv = -1;
    if (iequals(source, "texcoord") || iequals(source, "texcoord0")) uv = 0;
    else if (iequals(source, "texcoord1")) uv = 1;
    std::string t = target.text;
    std::transform(t.begin(), t.end(), t.begin(), [](unsigned char ch) { return char(std::tolower(ch)); });
    if (uv < 0 || !t.starts_with("texcoord")) continue;  // vertex, normal, color: always bound
    if (t == "texcoord") texcoord.fill(uv);
    else if (t.size() == 9 && t[8] >= '0' && t[8] <= '7') texcoord[size_t(t[8] - '0')] = uv;
    else return r.fail(target.span, "unknown target channel '" + target.text + "'");
  }
  state.stage_texcoord = texcoord;
  return true;
}

bool read_alpha_test(const ast::LegacyCommand& c, FixedFunctionState& state, Context& ctx) {
  static constexpr std::string_view kComparisons[] = {"Off", "Always", "Never", "Less", "LEqual", "Equal",
                                                      "GEqual", "Greater", "NotEqual"};
  const ast::Value& cmp = c.values.at(0);
  std::string_view canonical;
  for (std::string_view w : kComparisons) {
    if (cmp.kind == ast::Value::Kind::word && iequals(w, cmp.text)) canonical = w;
  }
  if (canonical.empty()) {
    std::string message = "unknown AlphaTest comparison '" + cmp.text + "'";
    if (auto s = suggest(cmp.text, kComparisons)) message += "; did you mean '" + std::string(*s) + "'?";
    ctx.error(DiagId::sema_bad_legacy_command, cmp.span, message);
    return false;
  }
  state.alpha_test = std::string(canonical);
  state.alpha_ref = {};
  if (c.values.size() > 1) {
    const ast::Value& ref = c.values[1];
    state.alpha_ref.span = ref.span;
    if (ref.kind == ast::Value::Kind::property) {
      state.alpha_ref.property = ref.text;
      check_property_reference(ref.text, ref.span, ctx);
    } else state.alpha_ref.literal[0] = std::strtof(ref.text.c_str(), nullptr);
  }
  return true;
}

void apply(const ast::LegacyCommand& c, FixedFunctionState& state, Context& ctx) {
  Reader r(c, ctx);
  const std::string& w = c.name;
  if (iequals(w, "Lighting")) {
    on_off(c, state.lighting, ctx);
  } else if (iequals(w, "SeparateSpecular")) {
    on_off(c, state.separate_specular, ctx);
  } else if (iequals(w, "ColorMaterial")) {
    const ast::Value& v = c.values.at(0);
    if (iequals(v.text, "AmbientAndDiffuse")) state.color_material = FfColorMaterial::ambient_and_diffuse;
    else if (iequals(v.text, "Emission")) state.color_material = FfColorMaterial::emission;
    else ctx.error(DiagId::sema_bad_legacy_command, v.span, "expected AmbientAndDiffuse or Emission after 'ColorMaterial'");
  } else if (iequals(w, "Color")) {
    if (!c.color.empty() || c.values.empty()) {
      std::vector<float> numbers(c.color.begin(), c.color.end());
      if (r.set_color(state.color, numbers, c.color_span)) state.has_color = true;
    } else if (c.values[0].kind == ast::Value::Kind::property) {
      state.color = {};
      state.color.property = c.values[0].text;
      state.color.span = c.values[0].span;
      state.has_color = true;
      check_property_reference(c.values[0].text, c.values[0].span, ctx);
    } else {
      ctx.error(DiagId::sema_bad_legacy_command, c.values[0].span, "expected '(r, g, b, a)' or '[_Prop]' after 'Color'");
    }
  } else if (iequals(w, "AlphaTest")) {
    read_alpha_test(c, state, ctx);
  } else if (iequals(w, "Material")) {
    read_material(r, state);
  } else if (iequals(w, "Fog")) {
    read_fog(r, state, ctx);
  } else if (iequals(w, "BindChannels")) {
    read_bind_channels(r, state);
  } else if (iequals(w, "SetTexture")) {
    FfStage stage;
    if (!read_set_texture(c, r, stage)) return;
    if (state.stages.size() == 8) {
      ctx.error(DiagId::sema_bad_legacy_command, c.keyword_span, "a Pass has at most 8 SetTexture stages");
      return;
    }
    state.stages.push_back(std::move(stage));
  }
}

}  // namespace

void apply_legacy_commands(const std::vector<const ast::LegacyCommand*>& commands, FixedFunctionState& state,
                           Context& ctx) {
  bool has_stages = std::any_of(commands.begin(), commands.end(),
                                [](const ast::LegacyCommand* c) { return iequals(c->name, "SetTexture"); });
  if (has_stages) state.stages.clear();
  for (const ast::LegacyCommand* c : commands) apply(*c, state, ctx);
}

}  // namespace facet::sema
