#include "devices/canopen/parameter_store.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string_view>

#include "sim/file_reader.h"

namespace canopen {

namespace {

constexpr const char* kHeader = "# vplant parameter store v1";

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

bool parse_hex_bytes(const std::string& text, Bytes& out) {
  if (text.size() % 2 != 0) return false;
  out.clear();
  for (std::size_t i = 0; i < text.size(); i += 2) {
    const int hi = hex_digit(text[i]), lo = hex_digit(text[i + 1]);
    if (hi < 0 || lo < 0) return false;
    out.push_back(static_cast<std::uint8_t>(hi << 4 | lo));
  }
  return true;
}

// A line as it can be printed: printable ASCII as is, every other byte as \xNN, at most 80
// characters of the line (a store file could hold one line of megabytes).
std::string escaped(std::string_view line) {
  constexpr std::size_t kMax = 80;
  std::string out;
  for (std::size_t i = 0; i < line.size() && i < kMax; ++i) {
    const auto c = static_cast<unsigned char>(line[i]);
    if (c >= 0x20 && c < 0x7F && c != '\\') {
      out += static_cast<char>(c);
    } else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02X", c);
      out += buf;
    }
  }
  if (line.size() > kMax) out += "...";
  return out;
}

bool write_all(int fd, const std::string& data) {
  std::size_t done = 0;
  while (done < data.size()) {
    const ssize_t n = ::write(fd, data.data() + done, data.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    done += static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

const ParameterStore::Value* ParameterStore::find(std::uint16_t index, std::uint8_t sub) const {
  auto it = values_.find({index, sub});
  return it == values_.end() ? nullptr : &it->second;
}

void ParameterStore::erase_range(std::uint16_t first, std::uint16_t last) {
  for (auto it = values_.begin(); it != values_.end();) {
    if (it->first.first >= first && it->first.first <= last) {
      it = values_.erase(it);
    } else {
      ++it;
    }
  }
}

std::string ParameterStore::where(const Value& v) const {
  return v.line > 0 ? path_ + ":" + std::to_string(v.line) : path_;
}

bool ParameterStore::load(std::string& error) {
  if (path_.empty()) return true;  // memory only: what was saved stays, like NV memory in a run
  values_.clear();
  std::string text, reason;
  switch (sim::read_input_file(path_, text, reason)) {
    case sim::ReadStatus::Missing: return true;  // nothing stored yet
    case sim::ReadStatus::Failed: error = path_ + ": " + reason; return false;
    case sim::ReadStatus::Ok: break;
  }
  std::map<Key, Value> loaded;
  int line_no = 0;
  for (std::size_t start = 0; start < text.size();) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    std::string_view line(text.data() + start, end - start);
    start = end + 1;
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line.empty() || line[0] == '#') continue;
    const std::string at = path_ + ":" + std::to_string(line_no) + ": ";
    // Format: IIII:SS=HEX or IIII:SS=$NODEID+HEX (hex, upper or lower case).
    Bytes key_bytes;
    const bool key_ok = line.size() >= 8 && line[4] == ':' && line[7] == '=' &&
                        parse_hex_bytes(std::string(line.substr(0, 4)) + std::string(line.substr(5, 2)), key_bytes);
    if (!key_ok) {
      error = at + "malformed entry '" + escaped(line) + "' (expected IIII:SS=HEX)";
      return false;
    }
    Value v;
    v.line = line_no;
    std::string_view hex = line.substr(8);
    if (hex.substr(0, 8) == "$NODEID+") {
      v.node_relative = true;
      hex.remove_prefix(8);
    }
    if (!parse_hex_bytes(std::string(hex), v.bytes)) {
      error = at + "malformed value '" + escaped(hex) + "' (expected pairs of hex digits)";
      return false;
    }
    const Key key{static_cast<std::uint16_t>(key_bytes[0] << 8 | key_bytes[1]), key_bytes[2]};
    if (auto it = loaded.find(key); it != loaded.end()) {
      error = at + "entry " + std::string(line.substr(0, 7)) + " given twice (first at line " + std::to_string(it->second.line) + ")";
      return false;
    }
    loaded[key] = std::move(v);
  }
  values_ = std::move(loaded);
  return true;
}

bool ParameterStore::save(std::string& error) const {
  if (path_.empty()) return true;
  std::ostringstream text;
  text << kHeader << '\n';
  char buf[16];
  for (const auto& [key, v] : values_) {
    std::snprintf(buf, sizeof buf, "%04X:%02X=", key.first, key.second);
    text << buf << (v.node_relative ? "$NODEID+" : "");
    for (auto b : v.bytes) {
      std::snprintf(buf, sizeof buf, "%02X", b);
      text << buf;
    }
    text << '\n';
  }
  const std::string tmp = path_ + ".tmp";
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) {
    error = "cannot write '" + tmp + "': " + std::strerror(errno);
    return false;
  }
  const bool ok = write_all(fd, text.str()) && ::fsync(fd) == 0;
  ::close(fd);
  if (!ok || ::rename(tmp.c_str(), path_.c_str()) != 0) {
    error = "cannot replace '" + path_ + "': " + std::strerror(errno);
    ::unlink(tmp.c_str());
    return false;
  }
  // Make the rename itself durable.
  const auto slash = path_.rfind('/');
  const std::string dir = slash == std::string::npos ? "." : (slash == 0 ? "/" : path_.substr(0, slash));
  const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dfd >= 0) {
    ::fsync(dfd);
    ::close(dfd);
  }
  return true;
}

}  // namespace canopen
