// `facet brdf`: argument parsing (CLI11), then one view of one or more models
// written as PNG or SVG. Every error is a line on `err` and exit code 1, with
// no output file.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <ostream>

#include "brdf_internal.h"

namespace facet::brdf {
namespace {

struct Options {
  std::vector<std::string> models;
  std::string view, output, light = "directional", channel = "luminance";
  double incidence = 45, exposure = 1, phi_d = 90;
  int size = 256, quadrature = 0, points = 90;
  bool list = false;
};

void add_options(CLI::App& app, Options& o) {
  app.add_option("models", o.models, "models, e.g. ggx:roughness=0.3 (see --list-models)");
  app.add_option("--view", o.view, "lit-sphere, polar, slice or albedo")
      ->check(CLI::IsMember({"lit-sphere", "polar", "slice", "albedo"}));
  app.add_option("-o,--output", o.output, "output file: .png or .svg");
  app.add_option("--incidence", o.incidence, "light angle from the normal, degrees (lit-sphere, polar; default 45)")
      ->check(CLI::Range(0.0, 89.0));
  app.add_option("--light", o.light, "lit-sphere lighting: directional (default) or furnace (uniform white)")
      ->check(CLI::IsMember({"directional", "furnace"}));
  app.add_option("--size", o.size, "image side in pixels (lit-sphere, slice; default 256)")->check(CLI::Range(8, 4096));
  app.add_option("--exposure", o.exposure, "multiplier before the sRGB encoding of images (default 1)")
      ->check(CLI::Range(1e-6, 1e6));
  app.add_option("--phi-d", o.phi_d, "slice difference azimuth, degrees (default 90)")->check(CLI::Range(0.0, 180.0));
  app.add_option("--channel", o.channel, "curve value: luminance (default), red, green or blue (polar, albedo)")
      ->check(CLI::IsMember({"luminance", "red", "green", "blue"}));
  app.add_option("--quadrature", o.quadrature,
                 "albedo integration grid side (default 128 for albedo, 48 per pixel for furnace)")
      ->check(CLI::Range(8, 2048));
  app.add_option("--points", o.points, "albedo curve points, theta_v 0..89 deg (default 90)")->check(CLI::Range(2, 1000));
  app.add_flag("--list-models", o.list, "print the model families and their parameters");
}

Channel channel_of(const std::string& s) {
  if (s == "red") return Channel::red;
  if (s == "green") return Channel::green;
  if (s == "blue") return Channel::blue;
  return Channel::luminance;
}

void list_models(std::ostream& out) {
  for (const FamilyInfo& f : model_families()) {
    out << f.name << "  (" << f.twins << ")\n";
    for (const ParamInfo& p : f.params) {
      std::string def = p.components == 1 || (p.default_value.r == p.default_value.g && p.default_value.g == p.default_value.b)
                            ? fmt::format("{}", p.default_value.r)
                            : fmt::format("{}/{}/{}", p.default_value.r, p.default_value.g, p.default_value.b);
      out << fmt::format("    {:<16} {} in [{}, {}], default {}{}{}\n", p.name, p.components == 3 ? "colour" : "number",
                         p.min, p.max, def, p.help.empty() ? "" : ": ", p.help);
    }
  }
}

bool ends_with(const std::string& s, const char* suffix) {
  std::string lower = s;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return lower.ends_with(suffix);
}

Result<void> check(const Options& o) {
  if (o.models.empty()) return failure("no model given (e.g. 'ggx:roughness=0.3'; --list-models lists them)");
  if (o.view.empty()) return failure("--view is required: lit-sphere, polar, slice or albedo");
  if (o.output.empty()) return failure("-o is required: an output file ending in .png or .svg");
  if (!ends_with(o.output, ".png") && !ends_with(o.output, ".svg")) {
    return failure(fmt::format("-o {}: the output must end in .png or .svg", o.output));
  }
  // Each option is bounded alone, not their product: a furnace sphere of
  // 4096 pixels a side integrates 48 x 48 directions a pixel (4 x 10^10
  // evaluations, hours). The defaults ask for at most 1.5 x 10^8.
  constexpr uint64_t kMaxEvaluations = uint64_t(1) << 28;
  uint64_t evaluations = 0;
  if (o.view == "lit-sphere" && o.light == "furnace") {
    uint64_t q = o.quadrature ? o.quadrature : 48;
    evaluations = uint64_t(o.size) * o.size * q * q;
  } else if (o.view == "albedo") {
    uint64_t q = o.quadrature ? o.quadrature : 128;
    evaluations = uint64_t(o.points) * q * q;
  }
  if (evaluations > kMaxEvaluations) {
    return failure(
        fmt::format("these options ask for {} evaluations of each model, more than {}: lower --size, "
                    "--points or --quadrature",
                    evaluations, kMaxEvaluations));
  }
  return {};
}

std::vector<std::string> labels_of(const std::vector<Model>& models) {
  std::vector<std::string> labels;
  for (const Model& m : models) labels.push_back(m.label);
  return labels;
}

// Image views: the PNG is the panels alone (pixel data, n*size x size); the
// SVG adds a caption and the legend.
Result<std::string> image_view(const Options& o, const std::vector<Model>& models, bool svg) {
  std::vector<Image8> panels;
  for (const Model& m : models) {
    Image im = o.view == "slice" ? render_slice(m, {o.size, o.phi_d})
                                 : render_lit_sphere(m, {o.size, o.incidence, o.light == "furnace",
                                                         o.quadrature ? o.quadrature : 48});
    panels.push_back(to_display(im, o.exposure));
  }
  if (!svg) return encode_png(side_by_side(panels));
  std::string caption =
      o.view == "slice"
          ? fmt::format("MERL slice: x = θh 0–90°, y = θd 0–90° (up), φd = {}°; π·f, exposure {}", o.phi_d, o.exposure)
      : o.light == "furnace" ? fmt::format("lit sphere in a uniform white environment, exposure {}", o.exposure)
                             : fmt::format("lit sphere, light at {}° (from the left), exposure {}", o.incidence, o.exposure);
  return to_svg(image_figure(panels, labels_of(models), caption));
}

Result<std::string> plot_view(const Options& o, const std::vector<Model>& models, bool svg) {
  Figure f;
  if (o.view == "polar") {
    std::vector<std::vector<PolarPoint>> curves;
    for (const Model& m : models) curves.push_back(polar_curve(m, o.incidence, channel_of(o.channel)));
    f = polar_figure(labels_of(models), curves, o.incidence, o.channel);
  } else {
    std::vector<std::vector<AlbedoPoint>> curves;
    for (const Model& m : models) curves.push_back(albedo_curve(m, o.points, 89.0, o.quadrature ? o.quadrature : 128));
    f = albedo_figure(labels_of(models), curves, channel_of(o.channel), o.channel);
  }
  if (svg) return to_svg(f);
  return to_png(f);
}

Result<void> run(const Options& o) {
  if (Result<void> ok = check(o); !ok) return ok;
  std::vector<Model> models;
  for (const std::string& spec : o.models) {
    Result<Model> m = parse_model(spec);
    if (!m) return unexpected(m.error());
    models.push_back(std::move(*m));
  }
  bool svg = ends_with(o.output, ".svg");
  Result<std::string> bytes =
      o.view == "lit-sphere" || o.view == "slice" ? image_view(o, models, svg) : plot_view(o, models, svg);
  if (!bytes) return unexpected(bytes.error());
  return write_file_whole(o.output, *bytes);
}

}  // namespace

int run_brdf_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  CLI::App app{"facet brdf: the BRDF Explorer's views of facet's lighting models (docs/brdf-explorer.md)", "facet brdf"};
  Options o;
  add_options(app, o);
  std::vector<std::string> reversed(args.rbegin(), args.rend());
  try {
    app.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    out << app.help();
    return 0;
  } catch (const CLI::ParseError& e) {
    err << "facet brdf: error: " << e.what() << "\n(run 'facet brdf --help' for the options)\n";
    return 1;
  }
  if (o.list) {
    list_models(out);
    return 0;
  }
  if (Result<void> ok = run(o); !ok) {
    err << "facet brdf: error: " << ok.error().reason << "\n";
    return 1;
  }
  return 0;
}

}  // namespace facet::brdf
