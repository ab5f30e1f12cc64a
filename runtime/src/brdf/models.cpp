// The models facet brdf offers: the model table's rows with a parameter form
// (facet/reference/models.h) and MERL files, and how a spec becomes a call of
// the CPU twins.
#include <fmt/format.h>

#include <charconv>
#include <map>
#include <memory>

#include "facet/reference/models.h"
#include "facet/runtime/brdf.h"

namespace facet::brdf {
namespace {

namespace ref = facet::reference;
using glm::dvec3;

using Params = ref::ModelParams;

// The rows of the model table (facet/reference/models.h) that have a
// parameter form, in the table's order.
struct Family {
  FamilyInfo info;
  const ref::LightingModel* row = nullptr;
};

FamilyInfo info_of(const ref::LightingModel& m) {
  FamilyInfo info{m.id, m.stdlib, {}};
  for (const ref::ModelParam& p : m.params) info.params.push_back({p.name, p.components, p.min, p.max, p.default_value, p.help});
  return info;
}

const std::vector<Family>& families() {
  static const std::vector<Family> all = [] {
    std::vector<Family> f;
    for (const ref::LightingModel& m : ref::lighting_models())
      if (m.bind) f.push_back({info_of(m), &m});
    return f;
  }();
  return all;
}

std::string known_names() {
  std::string s;
  for (const Family& f : families()) s += (s.empty() ? "" : ", ") + f.info.name;
  return s + ", merl:PATH";
}

std::string format_value(const ParamInfo& p, const dvec3& v) {
  if (p.components == 1 || (v.r == v.g && v.g == v.b)) return fmt::format("{}", v.r);
  return fmt::format("{}/{}/{}", v.r, v.g, v.b);
}

Result<double> parse_number(const std::string& text) {
  double d = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), d);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(d)) return failure();
  return d;
}

Result<dvec3> parse_value(const std::string& family, const ParamInfo& p, const std::string& text) {
  std::vector<std::string> parts;
  for (size_t start = 0;;) {
    size_t slash = text.find('/', start);
    parts.push_back(text.substr(start, slash - start));
    if (slash == std::string::npos) break;
    start = slash + 1;
  }
  if (parts.size() != 1 && !(p.components == 3 && parts.size() == 3)) {
    return failure(p.components == 1
                       ? fmt::format("model '{}': {} takes one number, not '{}'", family, p.name, text)
                       : fmt::format("model '{}': {} takes one number or r/g/b, not '{}'", family, p.name, text));
  }
  dvec3 v;
  for (size_t i = 0; i < 3; ++i) {
    Result<double> d = parse_number(parts[std::min(i, parts.size() - 1)]);
    if (!d) return failure(fmt::format("model '{}': {}: '{}' is not a number", family, p.name, text));
    if (*d < p.min || *d > p.max) {
      return failure(fmt::format("model '{}': {} = {} is outside [{}, {}]", family, p.name, *d, p.min, p.max));
    }
    v[int(i)] = *d;
  }
  return v;
}

Result<Params> parse_params(const Family& family, const std::string& list) {
  const std::string& name = family.info.name;
  Params p;
  for (const ParamInfo& info : family.info.params) p.values[info.name] = info.default_value;
  std::map<std::string, bool> seen;
  for (size_t start = 0;;) {
    size_t comma = list.find(',', start);
    std::string item = list.substr(start, comma - start);
    size_t eq = item.find('=');
    if (eq == std::string::npos || eq == 0) {
      return failure(fmt::format("model '{}': '{}' is not name=value", name, item));
    }
    std::string key = item.substr(0, eq);
    auto info = std::find_if(family.info.params.begin(), family.info.params.end(),
                             [&](const ParamInfo& i) { return i.name == key; });
    if (info == family.info.params.end()) {
      std::string names;
      for (const ParamInfo& i : family.info.params) names += (names.empty() ? "" : ", ") + i.name;
      return failure(fmt::format("model '{}': unknown parameter '{}' (parameters: {})", name, key, names));
    }
    if (seen[key]) return failure(fmt::format("model '{}': {} is given twice", name, key));
    seen[key] = true;
    Result<dvec3> v = parse_value(name, *info, item.substr(eq + 1));
    if (!v) return unexpected(v.error());
    p.values[key] = *v;
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return p;
}

std::string label_of(const Family& family, const Params& p) {
  std::string s = family.info.name;
  char sep = ':';
  for (const ParamInfo& info : family.info.params) {
    s += fmt::format("{}{}={}", sep, info.name, format_value(info, p.values.at(info.name)));
    sep = ',';
  }
  return s;
}

Result<Model> parse_merl_model(const std::string& path) {
  if (path.empty()) return failure("model 'merl' needs a file: merl:PATH");
  Result<MerlData> data = load_merl(path);
  if (!data) return unexpected(data.error());
  auto shared = std::make_shared<MerlData>(std::move(*data));
  return Model{"merl:" + path, [shared](const dvec3& v, const dvec3& l) {
                 if (v.z <= 0.0 || l.z <= 0.0) return dvec3(0.0);
                 return merl_lookup(*shared, v, l);
               }};
}

}  // namespace

const std::vector<FamilyInfo>& model_families() {
  static const std::vector<FamilyInfo> infos = [] {
    std::vector<FamilyInfo> v;
    for (const Family& f : families()) v.push_back(f.info);
    v.push_back({"merl", "merl_lookup (nearest bin of a MERL binary file; spec merl:PATH)", {}});
    return v;
  }();
  return infos;
}

Result<Model> parse_model(const std::string& spec) {
  size_t colon = spec.find(':');
  std::string name = spec.substr(0, colon);
  std::string rest = colon == std::string::npos ? "" : spec.substr(colon + 1);
  if (name == "merl") return parse_merl_model(rest);
  auto family = std::find_if(families().begin(), families().end(), [&](const Family& f) { return f.info.name == name; });
  if (family == families().end()) {
    return failure(fmt::format("unknown model '{}' (models: {})", name, known_names()));
  }
  Params p;
  for (const ParamInfo& info : family->info.params) p.values[info.name] = info.default_value;
  if (colon != std::string::npos) {
    Result<Params> parsed = parse_params(*family, rest);
    if (!parsed) return unexpected(parsed.error());
    p = std::move(*parsed);
  }
  return Model{label_of(*family, p), family->row->bind(p)};
}

}  // namespace facet::brdf
