// Stripping: keyword_rule pragmas and declarative strip filters.
#include <algorithm>
#include <cctype>
#include <charconv>

#include "facet/variants.h"

namespace facet::variants {
namespace {

bool has(const std::vector<std::string>& keywords, const std::string& k) {
  return std::find(keywords.begin(), keywords.end(), k) != keywords.end();
}

bool has_all(const std::vector<std::string>& keywords, const std::vector<std::string>& wanted) {
  return std::all_of(wanted.begin(), wanted.end(), [&](const std::string& k) { return has(keywords, k); });
}

bool applies_to_pass(const StripRule& rule, const std::string& pass_name, size_t pass_index) {
  if (rule.pass.empty()) return true;
  size_t index = 0;
  auto [end, ec] = std::from_chars(rule.pass.data(), rule.pass.data() + rule.pass.size(), index);
  if (ec == std::errc() && end == rule.pass.data() + rule.pass.size()) return index == pass_index;
  return rule.pass.size() == pass_name.size() &&
         std::equal(rule.pass.begin(), rule.pass.end(), pass_name.begin(), [](char a, char b) {
           return std::toupper(static_cast<unsigned char>(a)) == std::toupper(static_cast<unsigned char>(b));
         });
}

std::string joined(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : " ") + w;
  return out;
}

std::optional<std::string> broken_rule(const KeywordSpace& space, const std::vector<std::string>& keywords) {
  for (const KeywordRule& rule : space.rules) {
    if (!has(keywords, rule.keyword)) continue;
    if (rule.kind == RuleKind::excludes) {
      for (const std::string& other : rule.others) {
        if (has(keywords, other)) return "keyword_rule excludes " + rule.keyword + " " + joined(rule.others);
      }
    } else if (!has_all(keywords, rule.others)) {
      return "keyword_rule " + std::string(rule_kind_name(rule.kind)) + " " + rule.keyword + " " + joined(rule.others);
    }
  }
  return std::nullopt;
}

}  // namespace

std::string_view rule_kind_name(RuleKind kind) {
  switch (kind) {
    case RuleKind::requires_all: return "requires";
    case RuleKind::excludes: return "excludes";
    case RuleKind::implies: return "implies";
  }
  return "requires";
}

std::optional<std::string> strip_reason(const KeywordSpace& space, const std::vector<std::string>& keywords,
                                        const StripFilter& filter, const std::string& pass_name, size_t pass_index) {
  if (auto broken = broken_rule(space, keywords)) return broken;
  // An allow rule exempts a variant from deny rules; always_on/always_off
  // describe the feature set and hold regardless.
  bool allowed = false;
  for (const StripRule& rule : filter.rules) {
    if (rule.kind == StripKind::allow && applies_to_pass(rule, pass_name, pass_index)) {
      allowed = allowed || has_all(keywords, rule.keywords);
    }
  }
  for (const StripRule& rule : filter.rules) {
    if (!applies_to_pass(rule, pass_name, pass_index)) continue;
    switch (rule.kind) {
      case StripKind::allow:
        break;
      case StripKind::deny:
        if (!allowed && has_all(keywords, rule.keywords)) return "strip filter denies " + joined(rule.keywords);
        break;
      case StripKind::always_on:
        for (const std::string& k : rule.keywords) {
          if (!has(keywords, k)) return "strip filter: " + k + " is always on";
        }
        break;
      case StripKind::always_off:
        for (const std::string& k : rule.keywords) {
          if (has(keywords, k)) return "strip filter: " + k + " is always off";
        }
        break;
    }
  }
  return std::nullopt;
}

KeywordList apply_implications(const KeywordSpace& space, KeywordList keywords) {
  for (bool changed = true; changed;) {
    changed = false;
    for (const KeywordRule& rule : space.rules) {
      if (rule.kind != RuleKind::implies || !has(keywords, rule.keyword)) continue;
      for (const std::string& other : rule.others) {
        if (!has(keywords, other)) {
          keywords.push_back(other);
          changed = true;
        }
      }
    }
  }
  return keywords;
}

}  // namespace facet::variants
