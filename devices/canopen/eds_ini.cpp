#include "devices/canopen/eds_ini.h"

#include <algorithm>
#include <map>

namespace canopen::eds_detail {

void Diagnostics::error(int line, std::string reason) {
  items_.push_back(EdsError{{file_, line, 0}, std::move(reason), false});
  syntax_.push_back(false);
  ++errors_;
}

void Diagnostics::syntax_error(int line, std::string reason) {
  error(line, std::move(reason));
  syntax_.back() = true;
  ++syntax_errors_;
}

void Diagnostics::warning(int line, std::string reason) {
  items_.push_back(EdsError{{file_, line, 0}, std::move(reason), true});
  syntax_.push_back(false);
}

void Diagnostics::deviation(int line, const std::string& reason, const std::string& reading) {
  if (strict_) {
    error(line, reason);
  } else {
    warning(line, reason + ": " + reading);
  }
}

std::vector<EdsError> Diagnostics::sorted() const {
  std::vector<EdsError> out = items_;
  std::stable_sort(out.begin(), out.end(), [](const EdsError& a, const EdsError& b) { return a.mark.line < b.mark.line; });
  return out;
}

const EdsError* Diagnostics::first_error() const {
  const EdsError* best = nullptr;
  for (std::size_t i = 0; i < items_.size(); ++i) {
    const EdsError& e = items_[i];
    if (e.warning || (syntax_errors_ > 0 && !syntax_[i])) continue;
    if (!best || e.mark.line < best->mark.line) best = &e;
  }
  return best;
}

std::string to_upper(std::string_view s) {
  std::string out(s);
  for (auto& c : out)
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  return out;
}

std::string_view trim(std::string_view s) {
  const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; };
  while (!s.empty() && space(s.front())) s.remove_prefix(1);
  while (!s.empty() && space(s.back())) s.remove_suffix(1);
  return s;
}

const IniKey* IniSection::find(std::string_view upper_key) const {
  for (const auto& k : keys)
    if (k.upper == upper_key) return &k;
  return nullptr;
}

const IniKey* IniSection::take(std::string_view upper_key) const {
  for (std::size_t i = 0; i < keys.size(); ++i) {
    if (keys[i].upper == upper_key) {
      used[i] = true;
      return &keys[i];
    }
  }
  return nullptr;
}

const IniSection* IniFile::find(std::string_view upper_name) const {
  for (const auto& s : sections)
    if (s.upper == upper_name) return &s;
  return nullptr;
}

IniFile lex_ini(std::string_view text, Diagnostics& diag) {
  IniFile file;
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  std::map<std::string, int> section_lines;
  IniSection* current = nullptr;
  bool skipping = false;  // inside a duplicate section
  std::map<std::string, int> key_lines;
  int line_no = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t end = text.find('\n', pos);
    const std::string_view raw = text.substr(pos, end == std::string_view::npos ? std::string_view::npos : end - pos);
    pos = end == std::string_view::npos ? text.size() : end + 1;
    ++line_no;
    const std::string_view line = trim(raw);
    if (line.empty() || line.front() == ';') continue;
    if (line.front() == '[') {
      const std::size_t close = line.find(']');
      if (close == std::string_view::npos) {
        diag.syntax_error(line_no, "missing ']' in section header");
        current = nullptr;
        skipping = true;
        continue;
      }
      if (!trim(line.substr(close + 1)).empty()) {
        diag.syntax_error(line_no, "unexpected text after ']'");
      }
      const std::string_view name = trim(line.substr(1, close - 1));
      if (name.empty()) {
        diag.syntax_error(line_no, "empty section name");
        current = nullptr;
        skipping = true;
        continue;
      }
      const std::string upper = to_upper(name);
      if (auto it = section_lines.find(upper); it != section_lines.end()) {
        diag.syntax_error(line_no, "duplicate section [" + std::string(name) + "] (first at line " + std::to_string(it->second) + ")");
        current = nullptr;
        skipping = true;
        continue;
      }
      section_lines.emplace(upper, line_no);
      file.sections.push_back(IniSection{std::string(name), upper, line_no, {}, {}});
      current = &file.sections.back();
      skipping = false;
      key_lines.clear();
      continue;
    }
    const std::size_t eq = line.find('=');
    if (eq == std::string_view::npos) {
      diag.syntax_error(line_no, "expected '[section]' or 'key=value'");
      continue;
    }
    const std::string_view key = trim(line.substr(0, eq));
    if (key.empty()) {
      diag.syntax_error(line_no, "empty key name");
      continue;
    }
    if (skipping) continue;
    if (!current) {
      diag.syntax_error(line_no, "key '" + std::string(key) + "' outside of any section");
      continue;
    }
    const std::string upper = to_upper(key);
    if (auto it = key_lines.find(upper); it != key_lines.end()) {
      diag.syntax_error(line_no, "duplicate key '" + std::string(key) + "' in [" + current->name + "] (first at line " +
                              std::to_string(it->second) + ")");
      continue;
    }
    key_lines.emplace(upper, line_no);
    current->keys.push_back(IniKey{std::string(key), upper, std::string(trim(line.substr(eq + 1))), line_no});
    current->used.push_back(false);
  }
  file.line_count = line_no;
  return file;
}

}  // namespace canopen::eds_detail
