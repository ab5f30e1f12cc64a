// Bounds what glslang's preprocessor can be made to produce, before it runs.
//
// glslang expands macros with no limit and no hook to stop it: a dozen
// lines of `#define Mi M(i-1)+M(i-1)` ask for gigabytes. So the texts of a
// program (its chunks, then each file the includer returns) are read here
// first, and their macros' expansions are estimated:
//
//   * an object-like macro expands to at most the sum of its body's tokens,
//     with each macro it names replaced by that macro's estimate;
//   * a function-like macro to at most a + b * (its largest argument),
//     where b counts the uses of parameters, multiplied through the
//     function-like macros its body calls with them;
//   * every code line is estimated the same way, summed over the program.
//
// The estimate is an upper bound of the real expansion for the macros it
// knows (each definition counts at its largest, whether or not an #if
// skips it; a macro that names itself is not expanded again, as in the
// preprocessor). It knows the macros of the texts read so far: the
// program's own chunks are read before glslang starts, so a use in them of
// a macro that only an included file defines is counted as one token; the
// per-program time limit (worker.h) is the backstop for that case.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace facet::backend {

// The longest chain of macros naming macros (glslang re-expands each level
// on its own recursion).
inline constexpr int kMaxMacroDepth = 256;
// Different definitions of one name in one program (an #undef does not
// drop one: the budget reads a text before the files it includes, so it
// cannot tell which definition an include sees).
inline constexpr size_t kMaxDefinitions = 1024;

struct MacroExcess {
  size_t offset = 0;  // in the text given to add_text
  std::string message;
};

class MacroBudget {
 public:
  // `max_bytes`: the budget for the program's preprocessed text; 0: none.
  explicit MacroBudget(uint64_t max_bytes) : max_bytes_(max_bytes) {}

  struct Token {
    std::string_view text;
    size_t offset;
  };
  // The logical lines of a text (continuations joined) outside comments, as
  // one run of tokens: line k is [starts[k], starts[k + 1]) of `tokens`. A
  // string literal is one token; tokens view the text.
  struct TokenLines {
    std::vector<Token> tokens;
    std::vector<size_t> starts{0};
  };
  static TokenLines tokenize(std::string_view text);

  // Reads the #defines and code of one text; the first excess, if any.
  std::optional<MacroExcess> add_text(std::string_view text) { return add_lines(tokenize(text)); }
  // The same, of a text tokenize() has read (offsets are into that text).
  std::optional<MacroExcess> add_lines(const TokenLines& lines);

  uint64_t estimated_bytes() const { return total_; }

  // Size of an expansion: at most a + b * (the largest argument's size).
  struct Size {
    uint64_t a = 0, b = 0;
  };
  // One #define of a name (every definition is kept: an #if may pick any).
  struct Definition {
    bool function_like = false;
    std::vector<std::string> params;
    std::string body;  // the body's tokens, one space apart
    // Memo of measure(), valid while `generation` is the budget's.
    Size size;
    int depth = 0;
    uint64_t generation = UINT64_MAX;
    bool in_progress = false;
  };

 private:
  std::optional<MacroExcess> define(std::span<const Token> line);
  std::optional<MacroExcess> add_code(std::span<const Token> code);
  Size measure(Definition& d, int& depth);
  size_t measure_one(const std::vector<std::string_view>& tokens, size_t i, size_t end, const Definition* owner,
                     Size& size, int& depth);
  std::string too_big(std::string_view what, uint64_t bytes) const;

  uint64_t max_bytes_;
  uint64_t total_ = 0;
  uint64_t generation_ = 0;  // bumped by every #define: memos go stale
  // Looked up for every identifier of the program: hashed, and by
  // string_view without a copy.
  struct NameHash {
    using is_transparent = void;
    size_t operator()(std::string_view s) const { return std::hash<std::string_view>{}(s); }
  };
  struct Definitions {
    std::vector<Definition> all;
    std::unordered_set<std::string> signatures;  // params and body of each, to drop repeats
  };
  std::unordered_map<std::string, Definitions, NameHash, std::equal_to<>> macros_;
  // Names some macro body named: defining one of them makes memos stale.
  std::unordered_set<std::string, NameHash, std::equal_to<>> referenced_;
  int recursion_ = 0;
};

}  // namespace facet::backend
