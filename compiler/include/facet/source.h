// Source text ownership and positions. A span is two byte offsets into one
// file; line and column are computed only when printing (naga's Span).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace facet {

using FileId = uint32_t;
inline constexpr FileId kNoFile = UINT32_MAX;

// Half-open byte range [begin, end) in one file. A span with file == kNoFile
// has no location (command-line errors, I/O errors).
struct SourceSpan {
  FileId file = kNoFile;
  uint32_t begin = 0;
  uint32_t end = 0;

  bool has_location() const { return file != kNoFile; }
  bool operator==(const SourceSpan&) const = default;
};

// 1-based line and column; columns count bytes, as GCC does by default.
struct LineColumn {
  uint32_t line = 0;
  uint32_t column = 0;
};

// Owns every text that diagnostics may point into: .shader files, includes,
// generated code. FileIds are indices, stable for the map's lifetime. Safe to
// use from several threads at once (the parallel driver compiles variants
// concurrently into one map): files are immutable once added, and references
// returned by path()/text()/line_text() stay valid for the map's lifetime.
class SourceMap {
 public:
  SourceMap();
  ~SourceMap();
  SourceMap(SourceMap&&) noexcept;
  SourceMap& operator=(SourceMap&&) noexcept;

  FileId add_file(std::string path, std::string text);
  // The file already added under `path`, else a new one: atomic, so two
  // threads adding the same include get one FileId.
  FileId add_file_once(std::string path, std::string text);
  // The file already added under `path` with exactly this text (the newest
  // such), else a new one: a file edited since it was added gets a FileId of
  // its own, so that spans into the new text never point into the old.
  FileId add_file_version(std::string path, std::string text);

  size_t file_count() const;
  const std::string& path(FileId id) const;
  const std::string& text(FileId id) const;
  std::optional<FileId> find(std::string_view path) const;

  // Offsets past the end clamp to the end of the text.
  LineColumn line_column(FileId id, uint32_t offset) const;
  // The line's text without its newline; empty for lines out of range.
  std::string_view line_text(FileId id, uint32_t line) const;
  uint32_t line_count(FileId id) const;
  // Byte offset of (line, column), clamped into the file.
  uint32_t offset_of(FileId id, uint32_t line, uint32_t column) const;

 private:
  struct File {
    std::string path;
    std::string text;
    std::vector<uint32_t> line_starts;
  };
  const File* file(FileId id) const;  // nullptr when out of range

  struct Storage;  // the files and the mutex guarding the list
  std::unique_ptr<Storage> storage_;
};

}  // namespace facet
