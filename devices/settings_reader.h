// The one strict reader of a product's configuration settings (DeviceOptions::settings, text by
// name): each product's settings table is its sequence of calls, one per setting with its type,
// range and default (the value already in the target). Every product parses the same way:
// integers in decimal or 0x-hex, booleans as on/off/true/false/yes/no/1/0, choices from a fixed
// list; an unknown name is one error that lists the known names; a deprecated spelling is
// accepted with a warning naming the current one.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <limits>
#include <map>
#include <set>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace devices {

class SettingsReader {
 public:
  explicit SettingsReader(const std::map<std::string, std::string>& settings) : settings_(settings) {}

  void get(const std::string& name, std::uint64_t& value, std::uint64_t min, std::uint64_t max);
  void get(const std::string& name, std::int64_t& value, std::int64_t min, std::int64_t max);
  /// `old_name` is a deprecated spelling of setting `name` (call before reading `name`): its
  /// value is read as `name`'s, with a warning; giving both is an error.
  void deprecated(const std::string& old_name, const std::string& name);

  void get(const std::string& name, double& value, double min, double max);
  /// A number above `min` (excluded) up to `max`: a gain, a volume, a time constant.
  void get_above(const std::string& name, double& value, double min, double max);
  /// Any finite number.
  void get(const std::string& name, double& value);
  void get(const std::string& name, bool& value);
  void get(const std::string& name, std::string& value, std::size_t max_length);
  /// One of `choices`; `value` receives its position in the list.
  void choose(const std::string& name, int& value, std::initializer_list<const char*> choices) {
    choose(name, value, std::span<const char* const>(choices.begin(), choices.size()));
  }
  void choose(const std::string& name, int& value, std::span<const char* const> choices);
  /// One of `options` by its name, into an enum or bool field (kept when not given):
  /// `choose("pump_type", s.pump_type, {{"A4VSO", PumpType::A4VSO}, {"A2V", PumpType::A2V}})`.
  template <typename T>
  void choose(const std::string& name, T& field, std::initializer_list<std::pair<const char*, T>> options) {
    std::vector<const char*> names;
    int at = -1;
    for (const auto& [text, value] : options) {
      if (value == field) at = static_cast<int>(names.size());
      names.push_back(text);
    }
    const int before = at;
    choose(name, at, names);
    if (at >= 0 && at != before) field = options.begin()[at].second;
  }

  /// For a setting whose value only the product can check (a list, a free object index): the
  /// text given (nullptr: not given); reject() says why it cannot be used.
  const std::string* text(const std::string& name) { return find(name); }
  /// "setting name='text': reason" (the first error is the one reported).
  void reject(const std::string& name, const std::string& text, const std::string& reason);

  template <typename T>
  void get_uint(const std::string& name, T& value, std::uint64_t min, std::uint64_t max) {
    std::uint64_t v = value;
    get(name, v, min, max);
    value = static_cast<T>(v);
  }
  template <typename T>
  void get_int(const std::string& name, T& value, std::int64_t min, std::int64_t max) {
    std::int64_t v = value;
    get(name, v, min, max);
    value = static_cast<T>(v);
  }

  /// Any value of the integer type T (no narrowing: a value outside T is an error).
  template <typename T>
  void get_integer(const std::string& name, T& value) {
    if constexpr (std::is_signed_v<T>) {
      get_int(name, value, std::numeric_limits<T>::min(), std::numeric_limits<T>::max());
    } else {
      get_uint(name, value, 0, std::numeric_limits<T>::max());
    }
  }

  /// The first error, or an unknown setting; empty when everything was read.
  std::string finish() const;
  /// One line per deprecated name used ("setting 'old' is deprecated: use 'new'").
  const std::vector<std::string>& warnings() const { return warnings_; }

 private:
  const std::string* find(const std::string& name);
  /// find() and the text as a finite number in `v`; nullptr when not given or not a number (the error kept).
  const std::string* find_number(const std::string& name, double& v);
  void fail(const std::string& name, const std::string& text, const std::string& expected);
  void out_of_range(const std::string& name, const std::string& text, const std::string& min, const std::string& max);

  const std::map<std::string, std::string>& settings_;
  std::set<std::string> known_;
  std::map<std::string, std::string> deprecated_;  // new name -> old name
  std::vector<std::string> warnings_;
  std::string error_;
};

/// The one form of an unknown setting's error: "unknown setting 'x' (known: a, b, c)" (the YAML
/// reader's words for an unknown key), or
/// "(no settings)" when the product has none.
std::string unknown_setting(const std::string& name, const std::set<std::string>& known);

}  // namespace devices
