// A coarse split of preprocessed HLSL into top-level items and a call-graph
// walk from the entry point. It never needs to be exact about the language:
// anything it cannot split keeps the whole text, which only costs a compile.
#include "facet/reachability.h"
#include "facet/support/text.h"

#include <algorithm>
#include <cctype>
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

// ---- static initialisers that call functions ------------------------------

namespace {

// "static [const] TYPE NAME = INIT;": the '=' and the name, or npos when the
// item is no such declaration (an array, a list, or no initialiser).
size_t static_initializer(std::string_view item, std::string& name) {
  std::string_view t = trim(item);
  if (!t.starts_with("static") || t.size() < 7 || ident_char(t[6])) return std::string_view::npos;
  int depth = 0;
  for (size_t i = 0; i < item.size(); ++i) {
    char c = item[i];
    if (c == '(' || c == '[' || c == '{') ++depth;
    if (c == ')' || c == ']' || c == '}') --depth;
    if (c == '[' && depth == 1) return std::string_view::npos;  // an array
    if (c == ',' && depth == 0) return std::string_view::npos;  // a list
    if (c == '=' && depth == 0 && (i + 1 >= item.size() || item[i + 1] != '=')) {
      size_t end = i;
      while (end > 0 && !ident_char(item[end - 1])) --end;
      size_t begin = end;
      while (begin > 0 && ident_char(item[begin - 1])) --begin;
      name = std::string(item.substr(begin, end - begin));
      return name.empty() ? std::string_view::npos : i;
    }
  }
  return std::string_view::npos;
}

}  // namespace

std::string with_static_initializers_in_entry(const std::string& text, const std::string& entry) {
  std::vector<Item> items;
  if (!split_items(text, items)) return text;
  std::set<std::string> functions;
  const Item* entry_item = nullptr;
  for (const Item& item : items) {
    if (item.function.empty()) continue;
    functions.insert(item.function);
    if (item.function == entry && !entry_item) entry_item = &item;
  }
  if (!entry_item) return text;
  std::string out = text;
  std::string assignments;
  for (const Item& item : items) {
    if (!item.function.empty()) continue;
    bool calls = std::any_of(item.names.begin(), item.names.end(),
                             [&](const std::string& n) { return functions.count(n) > 0; });
    std::string name;
    std::string_view view(text.data() + item.begin, item.end - item.begin);
    size_t equals = calls ? static_initializer(view, name) : std::string_view::npos;
    if (equals == std::string_view::npos) continue;
    size_t semicolon = view.rfind(';');
    if (semicolon == std::string_view::npos || semicolon < equals) continue;
    std::string init(view.substr(equals + 1, semicolon - equals - 1));
    std::replace(init.begin(), init.end(), '\n', ' ');
    assignments += " " + name + " =" + init + ";";
    // "static [const] TYPE NAME" stays, without const; the initialiser
    // becomes blanks (its line breaks kept).
    std::string head(view.substr(0, equals));
    if (size_t c = head.find("const"); c != std::string::npos && (c + 5 >= head.size() || !ident_char(head[c + 5])) &&
                                        (c == 0 || !ident_char(head[c - 1]))) {
      head.replace(c, 5, "     ");
    }
    std::string replaced = head + ";";
    for (size_t k = equals; k < view.size(); ++k) replaced += view[k] == '\n' ? '\n' : ' ';
    replaced.resize(view.size(), ' ');
    out.replace(item.begin, item.end - item.begin, replaced);
  }
  if (assignments.empty()) return text;
  // After the '{' that opens the entry point's body, on its line.
  int parens = 0;
  for (size_t i = entry_item->begin; i < entry_item->end; ++i) {
    char c = text[i];
    if (c == '(') ++parens;
    if (c == ')') --parens;
    if (c == '{' && parens == 0) {
      out.insert(i + 1, assignments);
      return out;
    }
  }
  return text;
}

namespace {

// HLSL semantics ignore case.
bool same_semantic(std::string_view a, std::string_view b) { return iequals(a, b); }

// "[in] TYPE NAME : SEMANTIC" of one parameter: its type, name and
// semantic, or nullopt for any other shape.
struct FacingParameter {
  std::string type, name;
  bool vface = false;  // VFACE (+1/-1), or SV_IsFrontFace (1/0)
};

std::optional<FacingParameter> facing_parameter(std::string_view p) {
  std::vector<std::string_view> words;
  for (size_t i = 0; i < p.size();) {
    if (ident_char(p[i])) {
      size_t j = i;
      while (j < p.size() && ident_char(p[j])) ++j;
      words.push_back(p.substr(i, j - i));
      i = j;
    } else if (p[i] == ':') {
      words.push_back(":");
      ++i;
    } else if (p[i] == ' ' || p[i] == '\n' || p[i] == '\t' || p[i] == '\r') {
      ++i;
    } else {
      return std::nullopt;
    }
  }
  if (!words.empty() && words[0] == "in") words.erase(words.begin());
  if (words.size() != 4 || words[2] != ":" || !ident_start(words[1][0])) return std::nullopt;
  bool vface = same_semantic(words[3], "VFACE");
  if (!vface && !same_semantic(words[3], "SV_IsFrontFace")) return std::nullopt;
  if (words[0] == "bool") return std::nullopt;
  return FacingParameter{std::string(words[0]), std::string(words[1]), vface};
}

}  // namespace

std::string with_front_facing_as_bool(const std::string& text, const std::string& entry) {
  std::vector<Item> items;
  if (!split_items(text, items)) return text;
  auto found = std::find_if(items.begin(), items.end(), [&](const Item& item) { return item.function == entry; });
  if (found == items.end()) return text;
  // The entry's parameter list: from the '(' after its name to its match.
  std::string_view item(text.data() + found->begin, found->end - found->begin);
  size_t name = std::string_view::npos;
  for (size_t at = item.find(entry); at != std::string_view::npos; at = item.find(entry, at + 1)) {
    bool whole = (at == 0 || !ident_char(item[at - 1])) && at + entry.size() < item.size() &&
                 !ident_char(item[at + entry.size()]);
    size_t open = item.find_first_not_of(" \n\t", at + entry.size());
    if (whole && open != std::string_view::npos && item[open] == '(') {
      name = open;
      break;
    }
  }
  if (name == std::string_view::npos) return text;
  std::string out = text;
  std::string prologue;
  int depth = 0;
  size_t param_begin = name + 1, body = std::string_view::npos;
  std::vector<std::pair<size_t, size_t>> params;
  for (size_t i = name; i < item.size(); ++i) {
    char c = item[i];
    if (c == '(' || c == '[' || c == '<') ++depth;
    if (c == ')' || c == ']' || c == '>') --depth;
    if ((c == ',' && depth == 1) || (c == ')' && depth == 0)) {
      params.emplace_back(param_begin, i);
      param_begin = i + 1;
    }
    if (c == ')' && depth == 0) {
      body = item.find('{', i);
      break;
    }
  }
  if (body == std::string_view::npos) return text;
  // Replaced from the last, so that earlier offsets hold; each replacement
  // keeps the parameter's line breaks.
  for (auto it = params.rbegin(); it != params.rend(); ++it) {
    std::string_view p = item.substr(it->first, it->second - it->first);
    std::optional<FacingParameter> facing = facing_parameter(p);
    if (!facing) continue;
    std::string flag = facing->name + "_facet_front";
    std::string replacement = " bool " + flag + " : SV_IsFrontFace";
    for (char c : p) if (c == '\n') replacement += '\n';
    prologue += " " + facing->type + " " + facing->name + " = " + flag + (facing->vface ? " ? 1 : -1;" : " ? 1 : 0;");
    out.replace(found->begin + it->first, p.size(), replacement);
    body += replacement.size() - p.size();
  }
  if (prologue.empty()) return text;
  out.insert(found->begin + body + 1, prologue);
  return out;
}

}  // namespace facet
