// A light preprocessor-line scanner for program text: enough to find
// #pragma and #ifdef lines as the preprocessor would see them, without
// preprocessing. Lines are joined at backslash-newline first, then comments
// are removed (a block comment may span lines), as in translation phases 2-3.
#include "lower.h"

namespace facet::sema {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

// One logical line with comments replaced by a space; origin[i] is the
// offset in the chunk text of cleaned[i].
struct LogicalLine {
  std::string cleaned;
  std::vector<uint32_t> origin;
};

class Scanner {
 public:
  explicit Scanner(std::string_view text) : text_(text) {}

  bool next(LogicalLine& line) {
    if (pos_ >= text_.size()) return false;
    line.cleaned.clear();
    line.origin.clear();
    bool quoted = false;
    while (pos_ < text_.size()) {
      char c = text_[pos_];
      if (c == '\\' && continues_line(pos_)) {
        pos_ = skip_continuation(pos_);
        continue;
      }
      if (c == '\n') {
        ++pos_;
        break;
      }
      if (in_block_comment_) {
        if (c == '*' && peek_after(pos_) == '/') {
          in_block_comment_ = false;
          pos_ = skip_continuation(pos_ + 1) + 1;
          add(line, ' ', pos_ - 1);
        } else {
          ++pos_;
        }
        continue;
      }
      if (!quoted && c == '/' && peek_after(pos_) == '/') {
        skip_line_comment();
        continue;
      }
      if (!quoted && c == '/' && peek_after(pos_) == '*') {
        in_block_comment_ = true;
        pos_ = skip_continuation(pos_ + 1) + 1;
        continue;
      }
      if (c == '"') quoted = !quoted;
      add(line, c, pos_);
      ++pos_;
    }
    return true;
  }

 private:
  static void add(LogicalLine& line, char c, uint32_t at) {
    line.cleaned += c;
    line.origin.push_back(at);
  }

  // A backslash followed by optional spaces and a newline joins two lines.
  bool continues_line(size_t i) const {
    size_t k = i + 1;
    while (k < text_.size() && is_space(text_[k])) ++k;
    return k < text_.size() && text_[k] == '\n';
  }
  // Returns the position after any backslash-newlines starting at i.
  uint32_t skip_continuation(size_t i) const {
    while (i < text_.size() && text_[i] == '\\' && continues_line(i)) i = text_.find('\n', i) + 1;
    return uint32_t(i);
  }
  // The next character after i, looking through line continuations.
  char peek_after(size_t i) const {
    size_t k = skip_continuation(i + 1);
    return k < text_.size() ? text_[k] : '\0';
  }
  // A // comment runs to the end of the logical line.
  void skip_line_comment() {
    while (pos_ < text_.size() && text_[pos_] != '\n') {
      if (text_[pos_] == '\\' && continues_line(pos_)) pos_ = skip_continuation(pos_);
      else ++pos_;
    }
  }

  std::string_view text_;
  uint32_t pos_ = 0;
  bool in_block_comment_ = false;
};

std::vector<std::string> split_words(std::string_view s) {
  std::vector<std::string> words;
  size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && is_space(s[i])) ++i;
    size_t start = i;
    while (i < s.size() && !is_space(s[i])) ++i;
    if (i > start) words.emplace_back(s.substr(start, i - start));
  }
  return words;
}

std::optional<Directive> parse_directive(const LogicalLine& line, const ir::SourceChunk& chunk) {
  std::string_view s = line.cleaned;
  size_t hash = 0;
  while (hash < s.size() && is_space(s[hash])) ++hash;
  if (hash >= s.size() || s[hash] != '#') return std::nullopt;
  size_t i = hash + 1;
  while (i < s.size() && is_space(s[i])) ++i;
  size_t name_begin = i;
  while (i < s.size() && !is_space(s[i]) && s[i] != '(') ++i;
  size_t last = s.size();
  while (last > i && is_space(s[last - 1])) --last;
  Directive d;
  d.name = std::string(s.substr(name_begin, i - name_begin));
  std::string_view rest = s.substr(i, last - i);
  while (!rest.empty() && is_space(rest.front())) rest.remove_prefix(1);
  d.rest = std::string(rest);
  d.words = split_words(rest);
  uint32_t end = std::max(line.origin[hash] + 1, line.origin[std::max(last, hash + 1) - 1] + 1);
  d.span = {chunk.span.file, chunk.span.begin + line.origin[hash], chunk.span.begin + end};
  return d;
}

}  // namespace

std::vector<Directive> scan_directives(const ir::SourceChunk& chunk) {
  std::vector<Directive> out;
  Scanner scanner(chunk.text);
  LogicalLine line;
  while (scanner.next(line)) {
    if (line.cleaned.find('#') == std::string::npos) continue;
    if (auto d = parse_directive(line, chunk)) out.push_back(std::move(*d));
  }
  return out;
}

}  // namespace facet::sema
