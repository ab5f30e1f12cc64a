// A coarse split of preprocessed HLSL into top-level items and a call-graph
// walk from the entry point. It never needs to be exact about the language:
// anything it cannot split keeps the whole text, which only costs a compile.
#include "backend/reachable.h"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <string_view>
#include <vector>

namespace facet {
namespace {

bool ident_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool ident_char(char c) { return ident_start(c) || (c >= '0' && c <= '9'); }

struct Item {
  size_t begin = 0, end = 0;  // byte range in the text
  std::string function;        // the name when the item is a function definition
  std::set<std::string> names; // identifiers and string-literal words it mentions
};

const std::set<std::string_view> kNotFunctions = {"struct", "cbuffer", "tbuffer", "typedef", "namespace", "class",
                                                   "interface"};

// Splits `text` into top-level items; false when brackets do not balance.
bool split_items(const std::string& text, std::vector<Item>& items) {
  Item item;
  int braces = 0, parens = 0, brackets = 0;
  bool seen_paren = false, seen_brace = false, declares_type = false, has_content = false;
  std::string last_ident, name_before_paren, first_word;
  auto finish = [&](size_t end) {
    item.end = end;
    if (seen_paren && seen_brace && !declares_type && !name_before_paren.empty()) item.function = name_before_paren;
    items.push_back(std::move(item));
    item = Item{.begin = end};
    seen_paren = seen_brace = declares_type = has_content = false;
    last_ident.clear();
    name_before_paren.clear();
    first_word.clear();
  };
  for (size_t i = 0; i < text.size();) {
    char c = text[i];
    if (c == '#' && (i == 0 || text[i - 1] == '\n')) {  // a directive line: its own item between items
      size_t eol = text.find('\n', i);
      i = eol == std::string::npos ? text.size() : eol + 1;
      if (!has_content && braces == 0 && parens == 0) finish(i);
      continue;
    }
    if (c != ' ' && c != '\n') has_content = true;
    if (ident_start(c)) {
      size_t j = i;
      while (j < text.size() && ident_char(text[j])) ++j;
      std::string word = text.substr(i, j - i);
      if (first_word.empty()) first_word = word;
      if (braces == 0 && parens == 0 && kNotFunctions.count(word)) declares_type = true;
      item.names.insert(word);
      last_ident = word;
      i = j;
      continue;
    }
    if (c == '"') {
      size_t j = text.find('"', i + 1);
      if (j == std::string::npos) return false;
      std::string_view inside(text.data() + i + 1, j - i - 1);
      if (!inside.empty() && std::all_of(inside.begin(), inside.end(), ident_char)) item.names.insert(std::string(inside));
      i = j + 1;
      continue;
    }
    ++i;
    if (c == '[') {
      ++brackets;
    } else if (c == ']') {
      if (--brackets < 0) return false;
    } else if (c == '(') {
      if (braces == 0 && parens == 0 && brackets == 0 && !seen_paren && !seen_brace) {
        seen_paren = true;
        name_before_paren = last_ident;
      }
      ++parens;
    } else if (c == ')') {
      if (--parens < 0) return false;
    } else if (c == '{') {
      if (braces == 0) seen_brace = true;
      ++braces;
    } else if (c == '}') {
      if (--braces < 0) return false;
      // A function body or a cbuffer ends its item here; a struct waits for its ';'.
      bool block_ends_item = (seen_paren && !declares_type) || first_word == "cbuffer" || first_word == "tbuffer";
      if (braces == 0 && parens == 0 && block_ends_item) finish(i);
    } else if (c == ';' && braces == 0 && parens == 0) {
      finish(i);
    }
    if (c != '(' && !ident_char(c) && c != ' ' && c != '\n') last_ident.clear();
  }
  if (braces != 0 || parens != 0 || brackets != 0) return false;
  if (item.begin < text.size()) finish(text.size());
  return true;
}

// Which items to keep: declarations, and the functions reachable from
// `entry`; nullopt when the text does not split or has no such function.
std::optional<std::vector<Item>> split_reached(const std::string& text, const std::string& entry,
                                               std::vector<bool>& keep) {
  std::vector<Item> items;
  if (!split_items(text, items)) return std::nullopt;
  std::map<std::string, std::vector<size_t>> functions;  // name -> items (overloads)
  for (size_t i = 0; i < items.size(); ++i) {
    if (!items[i].function.empty()) functions[items[i].function].push_back(i);
  }
  if (!functions.count(entry)) return std::nullopt;
  // The entry point, and whatever a declaration outside functions names (a
  // static initialiser may call a function).
  std::set<std::string> reached{entry};
  std::vector<std::string> work{entry};
  for (const Item& item : items) {
    if (!item.function.empty()) continue;
    for (const std::string& used : item.names) {
      if (functions.count(used) && reached.insert(used).second) work.push_back(used);
    }
  }
  while (!work.empty()) {
    std::string name = work.back();
    work.pop_back();
    for (size_t i : functions[name]) {
      for (const std::string& used : items[i].names) {
        if (functions.count(used) && reached.insert(used).second) work.push_back(used);
      }
    }
  }
  keep.clear();
  for (const Item& item : items) keep.push_back(item.function.empty() || reached.count(item.function) > 0);
  return items;
}

}  // namespace

std::string reachable_text(const std::string& tokens, const std::string& entry) {
  std::vector<bool> keep;
  std::optional<std::vector<Item>> items = split_reached(tokens, entry, keep);
  if (!items) return tokens;
  std::string out;
  for (size_t i = 0; i < items->size(); ++i) {
    const Item& item = (*items)[i];
    if (keep[i]) out.append(tokens, item.begin, item.end - item.begin);
  }
  return out;
}

std::string without_unreachable_functions(const std::string& text, const std::string& entry) {
  std::vector<bool> keep;
  std::optional<std::vector<Item>> items = split_reached(text, entry, keep);
  if (!items) return text;
  std::string out;
  out.reserve(text.size());
  for (size_t i = 0; i < items->size(); ++i) {
    const Item& item = (*items)[i];
    if (keep[i]) {
      out.append(text, item.begin, item.end - item.begin);
    } else {
      out.append(size_t(std::count(text.begin() + long(item.begin), text.begin() + long(item.end), '\n')), '\n');
    }
  }
  return out;
}

}  // namespace facet
