// Error reporting shared by the lexer and the parser: turns byte offsets into
// spans of the parsed file and stops the parse after too many errors, so
// that a binary or hostile file cannot produce millions of diagnostics.
#pragma once

#include <cstdint>
#include <string>

#include "facet/diagnostics.h"
#include "facet/source.h"

namespace facet::shaderlab {

class Reporter {
 public:
  Reporter(FileId file, Diagnostics& diags, uint32_t max_errors)
      : file_(file), diags_(diags), max_errors_(max_errors) {}

  SourceSpan span(uint32_t begin, uint32_t end) const { return {file_, begin, end}; }

  // Adds an error; returns nullptr (and adds nothing) once the parse has
  // stopped. The error that reaches the limit is followed by one more that
  // says parsing stopped.
  Diagnostic* error(DiagId id, SourceSpan where, std::string message) {
    if (stopped_) return nullptr;
    ++errors_;
    Diagnostic& d = diags_.add(id, Severity::error, where, std::move(message));
    if (errors_ >= max_errors_) {
      stopped_ = true;
      // `d` may move when the vector grows: return the new last entry's
      // predecessor by index instead.
      size_t index = diags_.size() - 1;
      diags_.add(DiagId::parse_too_many_errors, Severity::error, where,
                 "too many errors (" + std::to_string(max_errors_) + "); parsing stopped");
      return &diags_.mutable_all()[index];
    }
    return &d;
  }

  // Adds a diagnostic with the id's default severity (notes, warnings).
  Diagnostic* report(DiagId id, SourceSpan where, std::string message) {
    if (stopped_) return nullptr;
    return &diags_.add(id, where, std::move(message));
  }

  bool stopped() const { return stopped_; }
  // Set once an error explains why the file ended early (an unterminated
  // comment or program, an unclosed block): the blocks around it are then
  // unclosed too, and saying so again for each would only be noise.
  void mark_early_eof() { early_eof_ = true; }
  bool early_eof() const { return early_eof_; }
  uint32_t error_count() const { return errors_; }
  FileId file() const { return file_; }

 private:
  FileId file_;
  Diagnostics& diags_;
  uint32_t max_errors_;
  uint32_t errors_ = 0;
  bool stopped_ = false;
  bool early_eof_ = false;
};

}  // namespace facet::shaderlab
