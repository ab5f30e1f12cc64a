#include "macro_budget.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

namespace facet::backend {
namespace {

constexpr uint64_t kSaturated = uint64_t(1) << 62;

uint64_t add(uint64_t x, uint64_t y) { return std::min(kSaturated, x + y); }
uint64_t mul(uint64_t x, uint64_t y) { return x != 0 && y > kSaturated / x ? kSaturated : std::min(kSaturated, x * y); }

bool ident_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

}  // namespace

MacroBudget::TokenLines MacroBudget::tokenize(std::string_view text) {
  TokenLines out;
  out.tokens.reserve(text.size() / 4);
  for (size_t i = 0; i < text.size();) {
    char c = text[i];
    char next = i + 1 < text.size() ? text[i + 1] : '\0';
    if (c == '\n') {
      out.starts.push_back(out.tokens.size());
      ++i;
    } else if (c == '\\' && (next == '\n' || (next == '\r' && i + 2 < text.size() && text[i + 2] == '\n'))) {
      i += next == '\n' ? 2 : 3;
    } else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v' || c == '\\') {
      ++i;
    } else if (c == '/' && next == '/') {
      i = std::min(text.find('\n', i), text.size());
    } else if (c == '/' && next == '*') {
      size_t end = text.find("*/", i + 2);
      i = end == std::string_view::npos ? text.size() : end + 2;
    } else {
      size_t begin = i++;
      if (ident_start(c) || std::isdigit(static_cast<unsigned char>(c))) {
        while (i < text.size() && (ident_char(text[i]) || text[i] == '.')) ++i;
      } else if (c == '"') {
        while (i < text.size() && text[i] != '"' && text[i] != '\n') i += text[i] == '\\' ? 2 : 1;
        i = std::min(i + 1, text.size());
      }
      out.tokens.push_back({text.substr(begin, i - begin), begin});
    }
  }
  out.starts.push_back(out.tokens.size());
  return out;
}

namespace {

std::vector<std::string_view> split_body(const std::string& body) {
  std::vector<std::string_view> out;
  std::string_view rest = body;
  while (!rest.empty()) {
    size_t space = rest.find(' ');
    out.push_back(rest.substr(0, space));
    rest = space == std::string_view::npos ? std::string_view() : rest.substr(space + 1);
  }
  return out;
}

// Index of the ')' that closes the '(' at `open`, or `end`.
size_t matching_paren(const std::vector<std::string_view>& tokens, size_t open, size_t end) {
  int depth = 0;
  for (size_t i = open; i < end; ++i) {
    if (tokens[i] == "(") ++depth;
    if (tokens[i] == ")" && --depth == 0) return i;
  }
  return end;
}

std::string mib(uint64_t bytes) {
  if (bytes >= kSaturated) return "more than 4 EiB";
  if (bytes % (uint64_t(1) << 20) == 0) return fmt::format("{} MiB", bytes >> 20);
  return fmt::format("{} bytes", bytes);
}

}  // namespace

std::string MacroBudget::too_big(std::string_view what, uint64_t bytes) const {
  return fmt::format("{} expands to about {} after macro expansion, more than the limit of {} per program "
                     "(--max-preprocessed-bytes)",
                     what, mib(bytes), mib(max_bytes_));
}

std::optional<MacroExcess> MacroBudget::add_lines(const TokenLines& lines) {
  std::span<const Token> all(lines.tokens);
  // The code since the last directive: a call's arguments do not span one.
  size_t code_begin = 0;
  for (size_t k = 0; k + 1 < lines.starts.size(); ++k) {
    size_t begin = lines.starts[k], end = lines.starts[k + 1];
    if (begin == end || all[begin].text != "#") continue;
    if (auto excess = add_code(all.subspan(code_begin, begin - code_begin))) return excess;
    code_begin = end;
    if (end - begin >= 3 && all[begin + 1].text == "define") {
      if (auto excess = define(all.subspan(begin, end - begin))) return excess;
    }
  }
  return add_code(all.subspan(code_begin));
}

std::optional<MacroExcess> MacroBudget::define(std::span<const Token> line) {
  const Token& name = line[2];
  if (!ident_start(name.text[0])) return std::nullopt;
  Definition d;
  size_t body = 3;
  // Function-like only when '(' touches the name.
  if (line.size() > 3 && line[3].text == "(" && line[3].offset == name.offset + name.text.size()) {
    d.function_like = true;
    for (body = 4; body < line.size() && line[body].text != ")"; ++body) {
      if (line[body].text != ",") d.params.emplace_back(line[body].text);
    }
    ++body;
  }
  for (size_t i = body; i < line.size(); ++i) {
    if (!d.body.empty()) d.body += ' ';
    d.body += line[i].text;
  }
  // Memos that may count this name as a plain token go stale.
  if (referenced_.count(name.text)) ++generation_;
  auto slot = macros_.find(name.text);
  if (slot == macros_.end()) slot = macros_.emplace(std::string(name.text), Definitions{}).first;
  Definitions& defs = slot->second;
  // Known by a hash: `#define M i` / `#undef M` 40,000 times compared each
  // new definition with all the others (minutes).
  std::string signature = d.function_like ? "(" : "";
  for (const std::string& p : d.params) signature += p + ",";
  signature += ")" + d.body;
  if (!defs.signatures.insert(std::move(signature)).second) return std::nullopt;
  // Every use weighs every definition: their number is bounded.
  if (defs.all.size() >= kMaxDefinitions) {
    return MacroExcess{name.offset, fmt::format("macro '{}' has more than {} different definitions in one program "
                                                "(every one is weighed at each use, as an #if may pick any)",
                                                name.text, kMaxDefinitions)};
  }
  defs.all.push_back(std::move(d));
  std::vector<Definition>& all = defs.all;
  int depth = 0;
  Size size = measure(all.back(), depth);
  if (max_bytes_ != 0 && add(size.a, size.b) > max_bytes_) {
    return MacroExcess{name.offset, too_big(fmt::format("macro '{}'", name.text), add(size.a, size.b))};
  }
  if (depth > kMaxMacroDepth) {
    return MacroExcess{name.offset, fmt::format("macro '{}' names macros nested more than {} deep", name.text,
                                                kMaxMacroDepth)};
  }
  return std::nullopt;
}

std::optional<MacroExcess> MacroBudget::add_code(std::span<const Token> code) {
  std::vector<std::string_view> tokens;
  tokens.reserve(code.size());
  for (const Token& t : code) tokens.push_back(t.text);
  for (size_t i = 0; i < tokens.size();) {
    Size size;
    int depth = 0;
    size_t next = measure_one(tokens, i, tokens.size(), nullptr, size, depth);
    total_ = add(total_, size.a);
    if (depth > kMaxMacroDepth) {
      return MacroExcess{code[i].offset, fmt::format("'{}' expands macros nested more than {} deep", tokens[i],
                                                     kMaxMacroDepth)};
    }
    if (max_bytes_ != 0 && total_ > max_bytes_) {
      return MacroExcess{code[i].offset, size.a * 2 > max_bytes_ ? too_big(fmt::format("'{}'", tokens[i]), size.a)
                                                                 : too_big("the program", total_)};
    }
    i = next;
  }
  return std::nullopt;
}

MacroBudget::Size MacroBudget::measure(Definition& d, int& depth) {
  if (d.generation == generation_) {
    depth = d.depth;
    return d.size;
  }
  d.in_progress = true;
  ++recursion_;
  std::vector<std::string_view> tokens = split_body(d.body);
  Size total;
  int deepest = 0;
  for (size_t i = 0; i < tokens.size();) {
    Size size;
    int inner = 0;
    i = measure_one(tokens, i, tokens.size(), &d, size, inner);
    total = {add(total.a, size.a), add(total.b, size.b)};
    deepest = std::max(deepest, inner);
  }
  d.in_progress = false;
  --recursion_;
  d.size = total;
  d.depth = deepest + 1;
  d.generation = generation_;
  depth = d.depth;
  return total;
}

// The size of the token (or macro call) at `i`; returns the index after it.
size_t MacroBudget::measure_one(const std::vector<std::string_view>& tokens, size_t i, size_t end,
                                const Definition* owner, Size& size, int& depth) {
  std::string_view token = tokens[i];
  if (owner && std::find(owner->params.begin(), owner->params.end(), token) != owner->params.end()) {
    size = {1, 1};
    return i + 1;
  }
  size = {token.size() + 1, 0};
  if (!ident_start(token[0])) return i + 1;
  if (owner && referenced_.find(token) == referenced_.end()) referenced_.emplace(token);
  auto found = macros_.find(token);
  if (found == macros_.end()) return i + 1;
  // Deeper than the limit: reported as such, without measuring on.
  if (recursion_ > kMaxMacroDepth) {
    depth = kMaxMacroDepth + 1;
    return i + 1;
  }
  bool call = i + 1 < end && tokens[i + 1] == "(";
  size_t close = call ? matching_paren(tokens, i + 1, end) : i;
  // The arguments' sizes, at their largest.
  Size arg;
  int arg_depth = 0;
  if (call) {
    for (size_t k = i + 2; k < close;) {
      Size one;
      int d = 0;
      k = measure_one(tokens, k, close, owner, one, d);
      arg = {add(arg.a, one.a), add(arg.b, one.b)};  // all arguments together: an upper bound of the largest
      arg_depth = std::max(arg_depth, d);
    }
  }
  Size best = size;
  int best_depth = 0;
  bool used_call = false;
  for (Definition& d : found->second.all) {
    if (d.in_progress || d.function_like != call) continue;
    int inner = 0;
    Size s = measure(d, inner);
    Size expanded = {add(s.a, mul(s.b, arg.a)), mul(s.b, arg.b)};
    if (expanded.a >= best.a) best = {expanded.a, std::max(best.b, expanded.b)};
    best.b = std::max(best.b, expanded.b);
    best_depth = std::max(best_depth, inner + (call ? arg_depth : 0));
    used_call |= call;
  }
  size = best;
  depth = best_depth;
  return used_call ? close + 1 : i + 1;
}

}  // namespace facet::backend
