#include "facet/source.h"

#include <algorithm>
#include <mutex>

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

struct SourceMap::Storage {
  mutable std::mutex mutex;
  std::vector<std::unique_ptr<const File>> files;  // pointees never move
};

SourceMap::SourceMap() : storage_(std::make_unique<Storage>()) {}
SourceMap::~SourceMap() = default;
SourceMap::SourceMap(SourceMap&&) noexcept = default;
SourceMap& SourceMap::operator=(SourceMap&&) noexcept = default;

FileId SourceMap::add_file(std::string path, std::string text) {
  auto f = std::make_unique<File>(File{std::move(path), std::move(text), {}});
  f->line_starts = compute_line_starts(f->text);
  std::lock_guard lock(storage_->mutex);
  storage_->files.push_back(std::move(f));
  return FileId(storage_->files.size() - 1);
}

FileId SourceMap::add_file_once(std::string path, std::string text) {
  {
    std::lock_guard lock(storage_->mutex);
    for (size_t i = 0; i < storage_->files.size(); ++i) {
      if (storage_->files[i]->path == path) return FileId(i);
    }
  }
  auto f = std::make_unique<File>(File{std::move(path), std::move(text), {}});
  f->line_starts = compute_line_starts(f->text);
  std::lock_guard lock(storage_->mutex);
  for (size_t i = 0; i < storage_->files.size(); ++i) {  // another thread may have won
    if (storage_->files[i]->path == f->path) return FileId(i);
  }
  storage_->files.push_back(std::move(f));
  return FileId(storage_->files.size() - 1);
}

const SourceMap::File* SourceMap::file(FileId id) const {
  std::lock_guard lock(storage_->mutex);
  return id < storage_->files.size() ? storage_->files[id].get() : nullptr;
}

size_t SourceMap::file_count() const {
  std::lock_guard lock(storage_->mutex);
  return storage_->files.size();
}

const std::string& SourceMap::path(FileId id) const {
  static const std::string none;
  const File* f = file(id);
  return f ? f->path : none;
}

const std::string& SourceMap::text(FileId id) const {
  static const std::string none;
  const File* f = file(id);
  return f ? f->text : none;
}

FileId SourceMap::add_file_version(std::string path, std::string text) {
  {
    std::lock_guard lock(storage_->mutex);
    for (size_t i = storage_->files.size(); i-- > 0;) {
      if (storage_->files[i]->path == path && storage_->files[i]->text == text) return FileId(i);
    }
  }
  return add_file(std::move(path), std::move(text));
}

std::optional<FileId> SourceMap::find(std::string_view path) const {
  std::lock_guard lock(storage_->mutex);
  for (size_t i = 0; i < storage_->files.size(); ++i) {
    if (storage_->files[i]->path == path) return FileId(i);
  }
  return std::nullopt;
}

LineColumn SourceMap::line_column(FileId id, uint32_t offset) const {
  const File* f = file(id);
  if (!f) return {};
  offset = std::min<uint32_t>(offset, uint32_t(f->text.size()));
  auto it = std::upper_bound(f->line_starts.begin(), f->line_starts.end(), offset);
  uint32_t line = uint32_t(it - f->line_starts.begin());  // 1-based
  uint32_t column = offset - f->line_starts[line - 1] + 1;
  return {line, column};
}

uint32_t SourceMap::line_count(FileId id) const {
  const File* f = file(id);
  return f ? uint32_t(f->line_starts.size()) : 0;
}

std::string_view SourceMap::line_text(FileId id, uint32_t line) const {
  const File* f = file(id);
  if (!f || line == 0 || line > f->line_starts.size()) return {};
  uint32_t begin = f->line_starts[line - 1];
  uint32_t end = line < f->line_starts.size() ? f->line_starts[line] - 1 : uint32_t(f->text.size());
  std::string_view view(f->text.data() + begin, end - begin);
  if (!view.empty() && view.back() == '\r') view.remove_suffix(1);
  return view;
}

uint32_t SourceMap::offset_of(FileId id, uint32_t line, uint32_t column) const {
  const File* f = file(id);
  if (!f) return 0;
  if (line == 0) line = 1;
  if (line > f->line_starts.size()) return uint32_t(f->text.size());
  uint32_t begin = f->line_starts[line - 1];
  uint32_t length = uint32_t(line_text(id, line).size());
  uint32_t col = column == 0 ? 0 : column - 1;
  return begin + std::min(col, length);
}

}  // namespace facet
