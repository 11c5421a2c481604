#include "devices/canopen/parameter_store.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

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

bool ParameterStore::load(std::string& error) {
  if (path_.empty()) return true;  // memory only: what was saved stays, like NV memory in a run
  values_.clear();
  std::ifstream in(path_);
  if (!in) return true;  // nothing stored yet
  std::map<Key, Value> loaded;
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty() || line[0] == '#') continue;
    // Format: IIII:SS=HEX or IIII:SS=$NODEID+HEX (hex, upper or lower case).
    const auto colon = line.find(':');
    const auto equals = line.find('=');
    Value v;
    std::string hex = equals == std::string::npos ? std::string{} : line.substr(equals + 1);
    Bytes key_bytes;
    const bool key_ok = colon == 4 && equals == 7 && parse_hex_bytes(line.substr(0, 4) + line.substr(5, 2), key_bytes);
    if (!key_ok) {
      error = path_ + ":" + std::to_string(line_no) + ": malformed entry '" + line + "'";
      return false;
    }
    const unsigned index = static_cast<unsigned>(key_bytes[0]) << 8 | key_bytes[1];
    const unsigned sub = key_bytes[2];
    if (hex.rfind("$NODEID+", 0) == 0) {
      v.node_relative = true;
      hex = hex.substr(8);
    }
    if (!parse_hex_bytes(hex, v.bytes)) {
      error = path_ + ":" + std::to_string(line_no) + ": malformed value '" + hex + "'";
      return false;
    }
    loaded[{static_cast<std::uint16_t>(index), static_cast<std::uint8_t>(sub)}] = std::move(v);
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
