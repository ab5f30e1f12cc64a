#include "facet/source.h"

#include <algorithm>

namespace facet {
namespace {

std::vector<uint32_t> compute_line_starts(const std::string& text) {
  std::vector<uint32_t> starts{0};
  for (uint32_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n') starts.push_back(i + 1);
  }
  return starts;
}

}  // namespace

FileId SourceMap::add_file(std::string path, std::string text) {
  File f{std::move(path), std::move(text), {}};
  f.line_starts = compute_line_starts(f.text);
  files_.push_back(std::move(f));
  return FileId(files_.size() - 1);
}

const std::string& SourceMap::path(FileId id) const {
  static const std::string none;
  return id < files_.size() ? files_[id].path : none;
}

const std::string& SourceMap::text(FileId id) const {
  static const std::string none;
  return id < files_.size() ? files_[id].text : none;
}

std::optional<FileId> SourceMap::find(std::string_view path) const {
  for (size_t i = 0; i < files_.size(); ++i) {
    if (files_[i].path == path) return FileId(i);
  }
  return std::nullopt;
}

LineColumn SourceMap::line_column(FileId id, uint32_t offset) const {
  if (id >= files_.size()) return {};
  const File& f = files_[id];
  offset = std::min<uint32_t>(offset, uint32_t(f.text.size()));
  auto it = std::upper_bound(f.line_starts.begin(), f.line_starts.end(), offset);
  uint32_t line = uint32_t(it - f.line_starts.begin());  // 1-based
  uint32_t column = offset - f.line_starts[line - 1] + 1;
  return {line, column};
}

uint32_t SourceMap::line_count(FileId id) const {
  return id < files_.size() ? uint32_t(files_[id].line_starts.size()) : 0;
}

std::string_view SourceMap::line_text(FileId id, uint32_t line) const {
  if (id >= files_.size() || line == 0 || line > files_[id].line_starts.size()) return {};
  const File& f = files_[id];
  uint32_t begin = f.line_starts[line - 1];
  uint32_t end = line < f.line_starts.size() ? f.line_starts[line] - 1 : uint32_t(f.text.size());
  std::string_view view(f.text.data() + begin, end - begin);
  if (!view.empty() && view.back() == '\r') view.remove_suffix(1);
  return view;
}

uint32_t SourceMap::offset_of(FileId id, uint32_t line, uint32_t column) const {
  if (id >= files_.size()) return 0;
  const File& f = files_[id];
  if (line == 0) line = 1;
  if (line > f.line_starts.size()) return uint32_t(f.text.size());
  uint32_t begin = f.line_starts[line - 1];
  uint32_t length = uint32_t(line_text(id, line).size());
  uint32_t col = column == 0 ? 0 : column - 1;
  return begin + std::min(col, length);
}

}  // namespace facet
