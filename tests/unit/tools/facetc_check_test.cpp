// facetc --check end to end: the line per shader, the summary, exit codes,
// -j independence, variant selection, bad inputs, and the JUnit and SARIF
// reports validated against schemas (tests/data/tools/) by xmllint and
// python3-jsonschema. CI installs both (scripts/install-deps.sh), so a
// missing validator fails these tests instead of skipping them.
#include <nlohmann/json.hpp>

#include <map>

#include "facetc/args.h"
#include "facetc_test_util.h"

namespace facet::tools::testing {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;

std::string cg_shader(const std::string& name, const std::string& extra, const std::string& fragment) {
  return "Shader \"Check/" + name + "\" {\n"
         "    SubShader {\n" + extra +
         "        Pass {\n"
         "            CGPROGRAM\n"
         "            #pragma vertex vert\n"
         "            #pragma fragment frag\n"
         "            float4 vert(float4 v : POSITION) : SV_POSITION { return v; }\n" + fragment +
         "            ENDCG\n"
         "        }\n"
         "    }\n"
         "}\n";
}

const std::string kGood =
    cg_shader("Good", "", "            fixed4 frag() : SV_Target { return fixed4(1, 0.5, 0.25, 1); }\n");
// The default variant compiles; the BROKEN one does not.
const std::string kVariants = cg_shader("Variants", "",
                                        "            #pragma multi_compile _ BROKEN\n"
                                        "            fixed4 frag() : SV_Target {\n"
                                        "            #ifdef BROKEN\n"
                                        "                return undeclared_thing;\n"
                                        "            #else\n"
                                        "                return fixed4(0, 1, 0, 1);\n"
                                        "            #endif\n"
                                        "            }\n");
// Missing ';' in the HLSL.
const std::string kBadHlsl =
    cg_shader("BadHlsl", "", "            fixed4 frag() : SV_Target { return fixed4(1, 0, 0, 1) }\n");
// A ShaderLab syntax error: a command without its value.
const std::string kBadSyntax = "Shader \"Check/BadSyntax\" {\n    SubShader {\n        Pass {\n            ZWrite\n"
                               "        }\n    }\n}\n";
// Compiles with one warning (a UsePass facet cannot resolve).
const std::string kWarn = cg_shader("Warn", "        UsePass \"Elsewhere/Missing/FORWARD\"\n",
                                    "            fixed4 frag() : SV_Target { return 1; }\n");

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

class FacetcCheckTest : public FacetcTest {
 protected:
  // shaders/ with two that fail, three that compile (one with a warning, one
  // in a subfolder) and a file that is not a shader.
  void write_project() {
    fs::create_directories(dir_ / "shaders" / "sub");
    write_all(dir_ / "shaders" / "good.shader", kGood);
    write_all(dir_ / "shaders" / "variants.shader", kVariants);
    write_all(dir_ / "shaders" / "bad_hlsl.shader", kBadHlsl);
    write_all(dir_ / "shaders" / "bad_syntax.shader", kBadSyntax);
    write_all(dir_ / "shaders" / "sub" / "warn.shader", kWarn);
    write_all(dir_ / "shaders" / "README.txt", "not a shader");
  }

  // The exit status of a validator run in the scratch folder.
  int shell(const std::string& command) const {
    int status = std::system(("cd " + shell_quote(dir_.string()) + " && " + command).c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
  }

  void expect_junit_valid(const std::string& file) const {
    ASSERT_EQ(shell("command -v xmllint >/dev/null"), 0) << "xmllint is missing: install libxml2-utils "
                                                            "(scripts/install-deps.sh)";
    std::string schema = std::string(FACET_TESTDATA_DIR) + "/tools/junit.xsd";
    EXPECT_EQ(shell("xmllint --noout --schema " + shell_quote(schema) + " " + shell_quote(file) + " 2>xmllint.txt"),
              0)
        << read_all(dir_ / "xmllint.txt");
  }

  // 0 when `file` validates against the SARIF subset schema.
  int sarif_validation(const std::string& file) const {
    std::string schema = std::string(FACET_TESTDATA_DIR) + "/tools/sarif-2.1.0-subset.schema.json";
    std::string script =
        "import json, sys, jsonschema\n"
        "schema = json.load(open(sys.argv[1]))\n"
        "jsonschema.Draft7Validator.check_schema(schema)\n"
        "jsonschema.Draft7Validator(schema, format_checker=jsonschema.FormatChecker())"
        ".validate(json.load(open(sys.argv[2])))\n";
    return shell("python3 -c " + shell_quote(script) + " " + shell_quote(schema) + " " + shell_quote(file) +
                 " 2>jsonschema.txt");
  }

  void expect_sarif_valid(const std::string& file) const {
    ASSERT_EQ(shell("python3 -c 'import jsonschema' 2>/dev/null"), 0)
        << "python3-jsonschema is missing (scripts/install-deps.sh)";
    EXPECT_EQ(sarif_validation(file), 0) << read_all(dir_ / "jsonschema.txt");
  }
};

TEST(FacetcCheckArgsTest, CheckParsesItsReportsAndVariantOptions) {
  ParsedArgs parsed = parse_args({"--check", "Assets", "x.shader", "--junit", "r.xml", "--sarif", "r.sarif",
                                  "--all-variants", "-j", "4"});
  ASSERT_TRUE(parsed.args) << parsed.text;
  EXPECT_EQ(parsed.args->mode, Mode::check);
  EXPECT_EQ(parsed.args->inputs, (std::vector<std::string>{"Assets", "x.shader"}));
  EXPECT_EQ(parsed.args->junit_file, "r.xml");
  EXPECT_EQ(parsed.args->sarif_file, "r.sarif");
  EXPECT_TRUE(parsed.args->all_variants);
  EXPECT_EQ(parsed.args->jobs, 4u);
  EXPECT_TRUE(parse_args({"--check", "--materials", "m.json", "Assets"}).args);
  ParsedArgs no_check = parse_args({"--sarif", "r.sarif", "x.shader"});
  EXPECT_EQ(no_check.exit_code, 2);
  EXPECT_NE(no_check.text.find("--junit and --sarif go with --check"), std::string::npos) << no_check.text;
  ParsedArgs output = parse_args({"--check", "a.shader", "b.shader", "-o", "x"});
  EXPECT_NE(output.text.find("--check writes no output"), std::string::npos) << output.text;
}

TEST_F(FacetcCheckTest, CheckFolderPrintsALinePerShaderAndTheSummary) {
  write_project();
  FacetcRun run = facetc({"--check", "shaders"});
  EXPECT_EQ(run.exit_code, 1) << run.err;
  std::vector<std::string> out = lines(run.out);
  ASSERT_EQ(out.size(), 6u) << run.out;
  // Sorted by path; the first error as file:line:col: error: message.
  EXPECT_THAT(out[0], StartsWith("FAIL shaders/bad_hlsl.shader: shaders/bad_hlsl.shader:8:66: error: expected ';'"));
  EXPECT_THAT(out[0], HasSubstr(": error: "));
  EXPECT_THAT(out[1], StartsWith("FAIL shaders/bad_syntax.shader: shaders/bad_syntax.shader:5:9: error: "));
  EXPECT_EQ(out[2], "ok   shaders/good.shader");
  EXPECT_EQ(out[3], "ok   shaders/sub/warn.shader (1 warning)");
  EXPECT_EQ(out[4], "ok   shaders/variants.shader");
  EXPECT_EQ(out[5], "3 of 5 shaders compile; 1 warning");
  // Every diagnostic, GCC-style, on standard error.
  EXPECT_THAT(run.err, HasSubstr("shaders/bad_syntax.shader:5:9: error: "));
  EXPECT_THAT(run.err, HasSubstr("shaders/sub/warn.shader:3:9: warning: UsePass"));
  // Nothing written: no package, no temporary file.
  EXPECT_THAT(files(), ElementsAre("shaders"));
}

TEST_F(FacetcCheckTest, CheckFilesThatCompileExitZero) {
  write_all(dir_ / "good.shader", kGood);
  write_all(dir_ / "variants.shader", kVariants);
  FacetcRun run = facetc({"--check", "variants.shader", "good.shader", "./good.shader"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  // FILE arguments in the order given, each once.
  EXPECT_EQ(run.out, "ok   variants.shader\nok   good.shader\n2 of 2 shaders compile; 0 warnings\n");
  EXPECT_EQ(run.err, "");
  write_all(dir_ / "warn.shader", kWarn);
  EXPECT_EQ(facetc({"--check", "warn.shader"}).exit_code, 0);
  FacetcRun werror = facetc({"--check", "-Werror", "warn.shader"});
  EXPECT_EQ(werror.exit_code, 1) << "-Werror: a warning fails the shader";
  EXPECT_THAT(werror.out, StartsWith("FAIL warn.shader: warn.shader:3:9: error: UsePass"));
}

TEST_F(FacetcCheckTest, CheckOutputDoesNotDependOnJobs) {
  write_project();
  for (int i = 0; i < 6; ++i) write_all(dir_ / "shaders" / ("extra" + std::to_string(i) + ".shader"), kGood);
  FacetcRun one = facetc({"--check", "shaders", "-j1"});
  FacetcRun four = facetc({"--check", "shaders", "-j4"});
  EXPECT_EQ(one.exit_code, 1);
  EXPECT_EQ(four.exit_code, 1);
  EXPECT_EQ(one.out, four.out);
  EXPECT_EQ(one.err, four.err);
  EXPECT_THAT(one.out, HasSubstr("9 of 11 shaders compile; 1 warning\n"));
}

TEST_F(FacetcCheckTest, CheckAllVariantsCompilesEveryVariant) {
  write_all(dir_ / "variants.shader", kVariants);
  FacetcRun fallback = facetc({"--check", "variants.shader"});
  EXPECT_EQ(fallback.exit_code, 0) << fallback.err;
  FacetcRun all = facetc({"--check", "--all-variants", "variants.shader"});
  EXPECT_EQ(all.exit_code, 1);
  EXPECT_THAT(all.out, StartsWith("FAIL variants.shader: variants.shader:11:"));
  EXPECT_THAT(all.out, HasSubstr("undeclared_thing"));
  EXPECT_THAT(all.out, HasSubstr("[in 1 of 2 variants]"));
  EXPECT_THAT(all.out, HasSubstr("\n0 of 1 shaders compile; 0 warnings\n"));
  FacetcRun keywords = facetc({"--check", "--keywords", "BROKEN", "variants.shader"});
  EXPECT_EQ(keywords.exit_code, 1) << "--keywords selects the variant to check";
}

TEST_F(FacetcCheckTest, CheckMaterialsCompileTheVariantsMaterialsUse) {
  write_all(dir_ / "feature.shader",
            cg_shader("Feature", "",
                      "            #pragma shader_feature BROKEN\n"
                      "            fixed4 frag() : SV_Target {\n"
                      "            #ifdef BROKEN\n"
                      "                return undeclared_thing;\n"
                      "            #else\n"
                      "                return 1;\n"
                      "            #endif\n"
                      "            }\n"));
  write_all(dir_ / "plain.json", R"({"materials": [{"name": "A", "shader": "Check/Feature"}]})");
  write_all(dir_ / "broken.json",
            R"({"materials": [{"name": "B", "shader": "Check/Feature", "keywords": ["BROKEN"]}]})");
  EXPECT_EQ(facetc({"--check", "--materials", "plain.json", "feature.shader"}).exit_code, 0);
  FacetcRun broken = facetc({"--check", "--materials", "broken.json", "feature.shader"});
  EXPECT_EQ(broken.exit_code, 1);
  EXPECT_THAT(broken.out, HasSubstr("undeclared_thing"));
}

TEST_F(FacetcCheckTest, CheckBadInputs) {
  write_all(dir_ / "good.shader", kGood);
  FacetcRun missing = facetc({"--check", "good.shader", "no/such/folder"});
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_EQ(missing.err, "facetc: error: 'no/such/folder' does not exist\n");
  EXPECT_EQ(missing.out, "") << "nothing is checked when a path is wrong";

  fs::create_directories(dir_ / "empty" / "deeper");
  write_all(dir_ / "empty" / "deeper" / "notes.txt", "no shaders here");
  FacetcRun empty = facetc({"--check", "empty"});
  EXPECT_EQ(empty.exit_code, 1);
  EXPECT_EQ(empty.err, "facetc: error: no .shader files under 'empty'\n");

  // Usage errors: exit 2.
  EXPECT_EQ(facetc({"--check"}).exit_code, 2);
  EXPECT_EQ(facetc({"--junit", "r.xml", "good.shader"}).exit_code, 2);
  EXPECT_EQ(facetc({"--check", "good.shader", "-o", "x.facetpkg"}).exit_code, 2);
  EXPECT_EQ(facetc({"--check", "--report", "good.shader"}).exit_code, 2);
  EXPECT_EQ(facetc({"--check", "--junit", "r", "--sarif", "r", "good.shader"}).exit_code, 2);
}

TEST_F(FacetcCheckTest, CheckUnwritableReportFailsBeforeCompiling) {
  write_all(dir_ / "good.shader", kGood);
  FacetcRun run = facetc({"--check", "good.shader", "--junit", "no/such/dir/report.xml"});
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_EQ(run.err, "facetc: error: cannot write the JUnit report 'no/such/dir/report.xml': there is no folder "
                     "'no/such/dir'\n");
  EXPECT_EQ(run.out, "");
  fs::create_directories(dir_ / "taken.sarif");
  FacetcRun folder = facetc({"--check", "good.shader", "--sarif", "taken.sarif"});
  EXPECT_EQ(folder.exit_code, 1);
  EXPECT_THAT(folder.err, HasSubstr("cannot write the SARIF report 'taken.sarif': it is a folder"));
  EXPECT_THAT(files(), ElementsAre("good.shader", "taken.sarif")) << "nothing half-written";
  EXPECT_TRUE(fs::is_empty(dir_ / "taken.sarif"));
}

TEST_F(FacetcCheckTest, CheckJUnitReportValidatesAgainstTheSchema) {
  write_project();
  FacetcRun run = facetc({"--check", "shaders", "--junit", "report.xml", "-j2"});
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_THAT(files(), ElementsAre("report.xml", "shaders")) << "the report, no temporary file";
  expect_junit_valid("report.xml");
  std::string xml = read_all(dir_ / "report.xml");
  EXPECT_THAT(xml, HasSubstr("<testsuite name=\"facetc --check\" tests=\"5\" failures=\"2\" errors=\"0\""));
  EXPECT_THAT(xml, HasSubstr("<testcase classname=\"shaders\" name=\"good.shader\" time=\""));
  EXPECT_THAT(xml, HasSubstr("<testcase classname=\"shaders/sub\" name=\"warn.shader\" time=\""));
  EXPECT_THAT(xml, HasSubstr("<failure message=\"shaders/bad_syntax.shader:5:9: error: "));
  EXPECT_THAT(xml, HasSubstr("type=\"hlsl_error\""));
  // The failure's text is every diagnostic, source excerpt included.
  EXPECT_THAT(xml, HasSubstr("    5 |         }\n"));
  // A shader that compiles with warnings keeps them in system-out.
  EXPECT_THAT(xml, HasSubstr("<system-out>shaders/sub/warn.shader:3:9: warning: UsePass"));

  // The validator does reject what the schema forbids.
  write_all(dir_ / "wrong.xml", "<testsuites><testsuite tests=\"1\"><testcase/></testsuite></testsuites>\n");
  std::string schema = std::string(FACET_TESTDATA_DIR) + "/tools/junit.xsd";
  EXPECT_NE(shell("xmllint --noout --schema " + shell_quote(schema) + " wrong.xml 2>/dev/null"), 0);
}

TEST_F(FacetcCheckTest, CheckSarifReportValidatesAgainstTheSchema) {
  write_project();
  FacetcRun run = facetc({"--check", "shaders", "--sarif", "report.sarif"});
  EXPECT_EQ(run.exit_code, 1) << run.err;
  expect_sarif_valid("report.sarif");
  auto log = nlohmann::json::parse(read_all(dir_ / "report.sarif"));
  EXPECT_EQ(log["version"], "2.1.0");
  EXPECT_EQ(log["$schema"], "https://json.schemastore.org/sarif-2.1.0.json");
  ASSERT_EQ(log["runs"].size(), 1u);
  const auto& sarif_run = log["runs"][0];
  EXPECT_EQ(sarif_run["tool"]["driver"]["name"], "facetc");
  EXPECT_TRUE(sarif_run["tool"]["driver"]["version"].is_string());
  std::vector<std::string> rule_ids;
  for (const auto& rule : sarif_run["tool"]["driver"]["rules"]) rule_ids.push_back(rule["id"]);
  EXPECT_THAT(rule_ids, ElementsAre("driver_usepass_unresolved", "hlsl_error", "parse_unexpected_token"));
  EXPECT_EQ(sarif_run["originalUriBaseIds"]["SRCROOT"]["uri"], "file://" + dir_.string() + "/");

  std::map<std::string, nlohmann::json> by_uri;
  for (const auto& result : sarif_run["results"]) {
    EXPECT_EQ(rule_ids.at(result["ruleIndex"].get<size_t>()), result["ruleId"]);
    by_uri[result["locations"][0]["physicalLocation"]["artifactLocation"]["uri"]] = result;
  }
  ASSERT_TRUE(by_uri.count("shaders/bad_syntax.shader"));
  const auto& syntax = by_uri["shaders/bad_syntax.shader"];
  EXPECT_EQ(syntax["level"], "error");
  EXPECT_EQ(syntax["ruleId"], "parse_unexpected_token");
  EXPECT_EQ(syntax["locations"][0]["physicalLocation"]["artifactLocation"]["uriBaseId"], "SRCROOT");
  EXPECT_EQ(syntax["locations"][0]["physicalLocation"]["region"]["startLine"], 5);
  EXPECT_EQ(syntax["locations"][0]["physicalLocation"]["region"]["startColumn"], 9);
  ASSERT_TRUE(by_uri.count("shaders/sub/warn.shader")) << "warnings are results too";
  EXPECT_EQ(by_uri["shaders/sub/warn.shader"]["level"], "warning");
  EXPECT_THAT(by_uri["shaders/sub/warn.shader"]["message"]["text"].get<std::string>(), HasSubstr("UsePass"));
  ASSERT_TRUE(by_uri.count("shaders/bad_hlsl.shader"));
  EXPECT_EQ(by_uri["shaders/bad_hlsl.shader"]["ruleId"], "hlsl_error");
  EXPECT_EQ(by_uri["shaders/bad_hlsl.shader"]["locations"][0]["physicalLocation"]["region"]["startLine"], 8);

  // The validator does reject what the schema forbids.
  write_all(dir_ / "wrong.sarif", R"({"version": "2.1.0", "runs": [{"tool": {"driver": {}}}]})");
  EXPECT_NE(sarif_validation("wrong.sarif"), 0) << "toolComponent.name is required";
}

TEST_F(FacetcCheckTest, CheckReportsOfAllGoodShaders) {
  write_all(dir_ / "good.shader", kGood);
  FacetcRun run = facetc({"--check", "good.shader", "--junit", "r.xml", "--sarif", "r.sarif"});
  EXPECT_EQ(run.exit_code, 0) << run.err;
  expect_junit_valid("r.xml");
  expect_sarif_valid("r.sarif");
  EXPECT_THAT(read_all(dir_ / "r.xml"), HasSubstr("<testcase classname=\".\" name=\"good.shader\" time=\""));
  EXPECT_THAT(read_all(dir_ / "r.xml"), Not(HasSubstr("<failure")));
  auto log = nlohmann::json::parse(read_all(dir_ / "r.sarif"));
  EXPECT_TRUE(log["runs"][0]["results"].empty());
  EXPECT_TRUE(log["runs"][0]["tool"]["driver"]["rules"].empty());
}

}  // namespace
}  // namespace facet::tools::testing
