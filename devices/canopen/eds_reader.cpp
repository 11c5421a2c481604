#include "devices/canopen/eds_reader.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>

#include "devices/canopen/eds_value.h"

namespace canopen::eds_detail {

namespace {

constexpr std::size_t kMaxNameLength = 241;         // CiA 306: ParameterName
constexpr std::size_t kMaxDescriptionLength = 243;  // CiA 306: Description

std::string hex4(unsigned v) {
  static constexpr char kDigits[] = "0123456789ABCDEF";
  std::string s = "0000";
  for (int i = 3; i >= 0; --i, v >>= 4) s[static_cast<std::size_t>(i)] = kDigits[v & 0xF];
  return s;
}
std::string hex_index(unsigned index) { return "0x" + hex4(index); }
bool is_pdo_mapping(unsigned index) { return (index >= 0x1600 && index <= 0x17FF) || (index >= 0x1A00 && index <= 0x1BFF); }
std::string code_name(ObjectCode c) {
  switch (c) {
    case ObjectCode::Domain: return "DOMAIN";
    case ObjectCode::DefType: return "DEFTYPE";
    case ObjectCode::DefStruct: return "DEFSTRUCT";
    case ObjectCode::Var: return "VAR";
    case ObjectCode::Array: return "ARRAY";
    case ObjectCode::Record: return "RECORD";
    case ObjectCode::Null: break;
  }
  return "NULL";
}

enum class ListKind { Mandatory, Optional, Manufacturer };
const char* list_name(ListKind k) {
  switch (k) {
    case ListKind::Mandatory: return "MandatoryObjects";
    case ListKind::Optional: return "OptionalObjects";
    case ListKind::Manufacturer: return "ManufacturerObjects";
  }
  return "";
}

struct Listing {
  ListKind list;
  int line;
};

// The sections that describe one object.
struct ObjectSections {
  const IniSection* main = nullptr;
  std::map<std::uint8_t, const IniSection*> subs;
  const IniSection* names = nullptr;
  const IniSection* values = nullptr;
};

struct SectionName {
  enum class Kind { Object, Sub, Name, Value, Ignored } kind;
  std::uint16_t index = 0;
  unsigned sub = 0;
};

bool is_hex(char c) { return std::isxdigit(static_cast<unsigned char>(c)) != 0; }
unsigned hex_digit(char c) {
  return c <= '9' ? static_cast<unsigned>(c - '0') : static_cast<unsigned>((c | 0x20) - 'a' + 10);
}

// "1018", "0x1018", "1018SUB2", "1018NAME", "1018VALUE", "1018DENOTATION", "1018OBJECTLINKS".
std::optional<SectionName> classify_object_section(std::string_view upper) {
  if (upper.substr(0, 2) == "0X") upper.remove_prefix(2);
  std::size_t n = 0;
  while (n < upper.size() && n < 4 && is_hex(upper[n])) ++n;
  if (n == 0) return std::nullopt;
  unsigned index = 0;
  for (std::size_t i = 0; i < n; ++i) index = index << 4 | hex_digit(upper[i]);
  const std::string_view rest = upper.substr(n);
  SectionName s{SectionName::Kind::Object, static_cast<std::uint16_t>(index), 0};
  if (rest.empty()) return s;
  if (rest == "NAME") return SectionName{SectionName::Kind::Name, s.index, 0};
  if (rest == "VALUE") return SectionName{SectionName::Kind::Value, s.index, 0};
  if (rest == "DENOTATION" || rest == "OBJECTLINKS") return SectionName{SectionName::Kind::Ignored, s.index, 0};
  if (rest.substr(0, 3) == "SUB" && rest.size() > 3 && rest.size() <= 6) {
    unsigned sub = 0;
    for (char c : rest.substr(3)) {
      if (!is_hex(c)) return std::nullopt;
      sub = sub << 4 | hex_digit(c);
    }
    return SectionName{SectionName::Kind::Sub, s.index, sub};
  }
  return std::nullopt;
}

bool is_tool_section(std::string_view upper) {
  if (upper == "TOOLS" || upper == "DEVICECOMISSIONING" || upper == "DEVICECOMMISSIONING" || upper == "DYNAMICCHANNELS" ||
      upper == "SUPPORTEDMODULES") {
    return true;
  }
  if (upper.substr(0, 4) == "TOOL" && upper.size() > 4 &&
      std::all_of(upper.begin() + 4, upper.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); })) {
    return true;
  }
  // Modular devices (CiA 306 §4.7): [M1ModuleInfo], [M1FixedObjects], [M1SubExtends], ...
  return upper.size() > 1 && upper[0] == 'M' && std::isdigit(static_cast<unsigned char>(upper[1]));
}

bool is_fixed_section(std::string_view upper) {
  return upper == "FILEINFO" || upper == "DEVICEINFO" || upper == "DUMMYUSAGE" || upper == "COMMENTS" ||
         upper == "MANDATORYOBJECTS" || upper == "OPTIONALOBJECTS" || upper == "MANUFACTUREROBJECTS";
}

std::optional<Access> parse_access(std::string_view text, ProcessData& process) {
  const std::string a = to_upper(trim(text));
  process = ProcessData::None;
  if (a == "RO") return Access::ReadOnly;
  if (a == "WO") return Access::WriteOnly;
  if (a == "RW") return Access::ReadWrite;
  if (a == "RWR") {
    process = ProcessData::Input;
    return Access::ReadWrite;
  }
  if (a == "RWW") {
    process = ProcessData::Output;
    return Access::ReadWrite;
  }
  if (a == "CONST") return Access::Const;
  return std::nullopt;
}

// hh:mm(AM|PM)
bool valid_time(std::string_view t) {
  const std::size_t colon = t.find(':');
  if (colon == std::string_view::npos || colon == 0 || colon > 2 || t.size() != colon + 5) return false;
  const auto digits = [](std::string_view s) {
    return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
  };
  const std::string suffix = to_upper(t.substr(colon + 3));
  return digits(t.substr(0, colon)) && digits(t.substr(colon + 1, 2)) && std::stoi(std::string(t.substr(0, colon))) <= 12 &&
         std::stoi(std::string(t.substr(colon + 1, 2))) < 60 && (suffix == "AM" || suffix == "PM");
}

// mm-dd-yyyy
bool valid_date(std::string_view d) {
  if (d.size() != 10 || d[2] != '-' || d[5] != '-') return false;
  for (std::size_t i : {0u, 1u, 3u, 4u, 6u, 7u, 8u, 9u})
    if (!std::isdigit(static_cast<unsigned char>(d[i]))) return false;
  const int month = std::stoi(std::string(d.substr(0, 2))), day = std::stoi(std::string(d.substr(3, 2)));
  return month >= 1 && month <= 12 && day >= 1 && day <= 31;
}

class Reader {
 public:
  Reader(const IniFile& ini, Diagnostics& diag, EdsFileInfo& info) : ini_(ini), diag_(diag), info_(info) {}

  std::optional<ObjectDictionary> run();

 private:
  // --- metadata sections ---
  void read_file_info();
  void read_device_info();
  void read_dummy_usage();
  void read_comments();
  std::string text_key(const IniSection* s, std::string_view key, bool required);
  template <typename T>
  void number_key(const IniSection* s, std::string_view key, std::uint64_t max, T& out, bool required);
  void flag_key(const IniSection* s, std::string_view key, bool& out, bool required);

  // --- objects ---
  void read_lists();
  void read_list(ListKind kind);
  void read_list_entries(ListKind kind);
  void collect_sections();
  void cross_check();
  void build_object(std::uint16_t index, const ObjectSections& secs);
  void build_compact_array(std::uint16_t index, const ObjectSections& secs, const std::string& name);
  void build_record(std::uint16_t index, const ObjectSections& secs);
  /// Reads the value keys of `s` into entry (index, sub). Returns false on error.
  bool build_entry(std::uint16_t index, std::uint8_t sub, const std::string& name, const IniSection& s, bool domain_object);
  void apply_names(std::uint16_t index, const IniSection& s, unsigned count);
  void apply_values(std::uint16_t index, const IniSection& s, unsigned count);
  void check_default_in_limits(const OdEntry& e, int line);
  std::string_view without_c_suffix(DataType type, std::string_view text, int line);
  void check_cob_ids();
  void check_mandatory();
  void add_dummy_objects();
  void add_compact_pdos();
  void build_compact_pdo(std::uint16_t comm, std::uint16_t map, int number, bool receive);
  void check_pdo_counts();
  void check_identity();
  void check_default_mappings();
  void warn_unknown_keys();

  void note_used(const IniSection* s) {
    if (s) used_sections_.insert(s);
  }

  const IniFile& ini_;
  Diagnostics& diag_;
  EdsFileInfo& info_;
  ObjectDictionary od_;
  std::map<std::uint16_t, Listing> listed_;
  std::map<std::uint16_t, ObjectSections> objects_;
  std::map<std::pair<std::uint16_t, std::uint8_t>, int> default_lines_;
  std::set<const IniSection*> used_sections_;
  std::map<const IniSection*, std::uint16_t> section_index_;  // object sections → their index
  std::set<std::uint16_t> failed_;  // objects with errors: their leftover keys are not "unknown"
  std::uint32_t dummy_mask_ = 0;
  bool mandatory_list_broken_ = false;
};

// ---- metadata ------------------------------------------------------------------------------------

std::string Reader::text_key(const IniSection* s, std::string_view key, bool required) {
  if (!s) return {};
  if (const auto* k = s->take(to_upper(key))) return k->value;
  if (required) diag_.warning(s->line, "missing " + std::string(key) + " in [" + s->name + "]");
  return {};
}

template <typename T>
void Reader::number_key(const IniSection* s, std::string_view key, std::uint64_t max, T& out, bool required) {
  if (!s) return;
  const auto* k = s->take(to_upper(key));
  if (!k) {
    if (required) diag_.warning(s->line, "missing " + std::string(key) + " in [" + s->name + "]");
    return;
  }
  std::string reason;
  if (auto v = parse_count(k->value, max, reason)) {
    out = static_cast<T>(*v);
  } else {
    diag_.warning(k->line, k->name + ": " + reason);
  }
}

void Reader::flag_key(const IniSection* s, std::string_view key, bool& out, bool required) {
  std::uint8_t v = out ? 1 : 0;
  number_key(s, key, 1, v, required);
  out = v != 0;
}

void Reader::read_file_info() {
  const IniSection* s = ini_.find("FILEINFO");
  if (!s) {
    diag_.warning(1, "missing section [FileInfo]");
    return;
  }
  note_used(s);
  info_.file_name = text_key(s, "FileName", true);
  number_key(s, "FileVersion", 255, info_.file_version, true);
  number_key(s, "FileRevision", 255, info_.file_revision, true);
  if (const auto* k = s->take("EDSVERSION")) {
    info_.eds_version = k->value;
    const std::size_t dot = k->value.find('.');
    const bool ok = dot != std::string::npos && dot > 0 && dot + 1 < k->value.size() &&
                    std::all_of(k->value.begin(), k->value.end(),
                                [](char c) { return c == '.' || std::isdigit(static_cast<unsigned char>(c)); });
    if (!ok) diag_.warning(k->line, "EDSVersion '" + k->value + "' is not of the form x.y (CiA 306: 4.0)");
  } else {
    diag_.warning(s->line, "missing EDSVersion in [FileInfo]");
  }
  info_.description = text_key(s, "Description", true);
  if (info_.description.size() > kMaxDescriptionLength) {
    diag_.warning(s->find("DESCRIPTION")->line, "Description longer than 243 characters");
  }
  for (auto [key, field, is_time, required] :
       {std::tuple{"CreationTime", &info_.creation_time, true, true}, std::tuple{"CreationDate", &info_.creation_date, false, true},
        std::tuple{"ModificationTime", &info_.modification_time, true, false},
        std::tuple{"ModificationDate", &info_.modification_date, false, false}}) {
    const auto* k = s->take(to_upper(key));
    if (!k) {
      if (required) diag_.warning(s->line, std::string("missing ") + key + " in [FileInfo]");
      continue;
    }
    *field = k->value;
    if (k->value.empty() && !required) continue;
    if (is_time ? !valid_time(k->value) : !valid_date(k->value)) {
      diag_.warning(k->line, std::string(key) + " '" + k->value + (is_time ? "' is not hh:mm(AM|PM)" : "' is not mm-dd-yyyy"));
    }
  }
  info_.created_by = text_key(s, "CreatedBy", true);
  info_.modified_by = text_key(s, "ModifiedBy", false);
  (void)s->take("LASTEDS");  // written by some tools; harmless
}

void Reader::read_device_info() {
  const IniSection* s = ini_.find("DEVICEINFO");
  if (!s) {
    diag_.warning(1, "missing section [DeviceInfo]");
    return;
  }
  note_used(s);
  info_.vendor_name = text_key(s, "VendorName", false);
  number_key(s, "VendorNumber", 0xFFFFFFFFu, info_.vendor_number, false);
  info_.product_name = text_key(s, "ProductName", false);
  number_key(s, "ProductNumber", 0xFFFFFFFFu, info_.product_number, false);
  number_key(s, "RevisionNumber", 0xFFFFFFFFu, info_.revision_number, false);
  info_.order_code = text_key(s, "OrderCode", false);
  info_.baud_rates_kbit.clear();
  for (unsigned rate : {10u, 20u, 50u, 125u, 250u, 500u, 800u, 1000u}) {
    bool supported = false;
    flag_key(s, "BaudRate_" + std::to_string(rate), supported, true);
    if (supported) info_.baud_rates_kbit.push_back(rate);
  }
  flag_key(s, "SimpleBootUpMaster", info_.simple_boot_up_master, true);
  flag_key(s, "SimpleBootUpSlave", info_.simple_boot_up_slave, true);
  number_key(s, "Granularity", 64, info_.granularity, true);
  flag_key(s, "DynamicChannelsSupported", info_.dynamic_channels, true);
  number_key(s, "CompactPDO", 255, info_.compact_pdo, false);
  flag_key(s, "GroupMessaging", info_.group_messaging, true);
  number_key(s, "NrOfRXPDO", 512, info_.nr_of_rx_pdo, true);
  number_key(s, "NrOfTXPDO", 512, info_.nr_of_tx_pdo, true);
  flag_key(s, "LSS_Supported", info_.lss_supported, true);
  (void)s->take("NG_SLAVE");  // CANopenNode's network-management extension
  (void)s->take("NG_MASTER");
  (void)s->take("CANOPENSAFETYSUPPORTED");
}

void Reader::read_dummy_usage() {
  const IniSection* s = ini_.find("DUMMYUSAGE");
  info_.dummy_usage = 0;
  if (!s) return;
  note_used(s);
  for (unsigned t = 1; t <= 7; ++t) {
    bool used = false;
    flag_key(s, "Dummy000" + std::to_string(t), used, false);
    if (used) dummy_mask_ |= 1u << t;
  }
  info_.dummy_usage = static_cast<std::uint8_t>(dummy_mask_);
}

void Reader::read_comments() {
  const IniSection* s = ini_.find("COMMENTS");
  if (!s) return;
  note_used(s);
  unsigned lines = 0;
  number_key(s, "Lines", 0xFFFF, lines, true);
  info_.comments.clear();
  for (unsigned i = 1; i <= lines; ++i) {
    const auto* k = s->take("LINE" + std::to_string(i));
    if (!k) {
      diag_.warning(s->find("LINES")->line, "Line" + std::to_string(i) + " missing in [Comments] (Lines=" + std::to_string(lines) + ")");
    }
    info_.comments.push_back(k ? k->value : std::string{});
  }
}

// ---- object lists --------------------------------------------------------------------------------

void Reader::read_lists() {
  read_list(ListKind::Mandatory);
  read_list(ListKind::Optional);
  read_list(ListKind::Manufacturer);
}

void Reader::read_list(ListKind kind) {
  const std::size_t errors_before = diag_.error_count();
  read_list_entries(kind);
  // A broken mandatory list would also report its objects as missing: say only what is broken.
  if (kind == ListKind::Mandatory && diag_.error_count() != errors_before) mandatory_list_broken_ = true;
}

void Reader::read_list_entries(ListKind kind) {
  const std::string name = list_name(kind);
  const IniSection* s = ini_.find(to_upper(name));
  if (!s) {
    if (kind == ListKind::Mandatory) diag_.error(1, "missing section [MandatoryObjects]");
    return;
  }
  note_used(s);
  const auto* count_key = s->take("SUPPORTEDOBJECTS");
  if (!count_key) {
    diag_.error(s->line, "missing SupportedObjects in [" + name + "]");
    return;
  }
  std::string reason;
  const auto count = parse_count(count_key->value, 0xFFFF, reason);
  if (!count) {
    diag_.error(count_key->line, "SupportedObjects: " + reason);
    return;
  }
  std::set<std::uint64_t> positions;
  for (std::size_t i = 0; i < s->keys.size(); ++i) {
    const IniKey& k = s->keys[i];
    if (k.upper == "SUPPORTEDOBJECTS") continue;
    s->used[i] = true;
    const bool numeric = !k.name.empty() && std::all_of(k.name.begin(), k.name.end(),
                                                         [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
    const std::uint64_t pos = numeric && k.name.size() < 7 ? std::stoull(k.name) : 0;
    if (!numeric || pos == 0) {
      diag_.error(k.line, "unexpected key '" + k.name + "' in [" + name + "]");
      continue;
    }
    positions.insert(pos);  // entries beyond SupportedObjects: a deviation, reported below
    const auto index = parse_count(k.value, 0xFFFF, reason);
    if (!index || *index == 0) {
      diag_.error(k.line, "entry " + k.name + ": " + (index ? "index 0x0000 is not an object" : reason));
      continue;
    }
    const auto idx = static_cast<std::uint16_t>(*index);
    if (auto it = listed_.find(idx); it != listed_.end()) {
      diag_.error(k.line, hex_index(idx) + " is listed twice (first at line " + std::to_string(it->second.line) + ")");
      continue;
    }
    listed_.emplace(idx, Listing{kind, k.line});
    const bool manufacturer_range = idx >= 0x2000 && idx <= 0x5FFF;
    const bool mandatory = idx == 0x1000 || idx == 0x1001 || idx == 0x1018;
    if (kind == ListKind::Manufacturer && !manufacturer_range) {
      diag_.warning(k.line, hex_index(idx) + " is not a manufacturer-specific object (0x2000-0x5FFF)");
    } else if (kind != ListKind::Manufacturer && manufacturer_range) {
      diag_.warning(k.line, hex_index(idx) + " is a manufacturer-specific object: it belongs in [ManufacturerObjects]");
    } else if (kind != ListKind::Mandatory && mandatory) {
      diag_.warning(k.line, hex_index(idx) + " is a mandatory object: it belongs in [MandatoryObjects]");
    }
  }
  // Entries 1..k present and SupportedObjects < k: the count is too low (tools that count only
  // the objects they generated); every entry listed is read.
  const std::uint64_t present = positions.size();
  if (!positions.empty() && *positions.rbegin() > *count) {
    const std::uint64_t highest = *positions.rbegin();
    diag_.deviation(count_key->line,
                    "SupportedObjects=" + std::to_string(*count) + " but [" + name + "] lists entries up to " +
                        std::to_string(highest),
                    "the entries listed are read, as if SupportedObjects=" + std::to_string(highest));
    for (std::uint64_t p = 1; p <= highest; ++p) {
      if (!positions.count(p))
        diag_.error(count_key->line, "entry " + std::to_string(p) + " missing in [" + name + "] (entries up to " +
                                         std::to_string(highest) + ")");
    }
    return;
  }
  // Entries 1..k present and SupportedObjects > k: the count is too high, nothing is out of place.
  if (present < *count && (present == 0 || *positions.rbegin() == present)) {
    diag_.deviation(count_key->line,
                    "SupportedObjects=" + std::to_string(*count) + " but [" + name + "] lists " + std::to_string(present) +
                        (present == 1 ? " entry" : " entries"),
                    "the " + std::to_string(present) + (present == 1 ? " entry listed is read" : " entries listed are read"));
    return;
  }
  for (std::uint64_t p = 1; p <= *count; ++p) {
    if (!positions.count(p)) {
      diag_.error(count_key->line, "entry " + std::to_string(p) + " missing in [" + name + "] (SupportedObjects=" +
                                       std::to_string(*count) + ")");
    }
  }
}

// ---- object sections -----------------------------------------------------------------------------

void Reader::collect_sections() {
  std::map<std::pair<int, unsigned>, int> seen;  // (kind, index<<8|sub) → line, for [1000] vs [0x1000]
  for (const auto& s : ini_.sections) {
    if (is_fixed_section(s.upper)) continue;
    if (is_tool_section(s.upper)) continue;
    const auto name = classify_object_section(s.upper);
    if (!name) {
      diag_.warning(s.line, "unknown section [" + s.name + "] ignored");
      continue;
    }
    if (name->kind == SectionName::Kind::Ignored) continue;
    note_used(&s);
    section_index_[&s] = name->index;
    if (name->index == 0) {
      diag_.error(s.line, "[" + s.name + "]: index 0x0000 is not an object");
      continue;
    }
    if (name->kind == SectionName::Kind::Sub && name->sub > 0xFE) {
      diag_.error(s.line, "[" + s.name + "]: sub-index " + std::to_string(name->sub) + " is out of range (0..254)");
      continue;
    }
    const auto key = std::make_pair(static_cast<int>(name->kind), static_cast<unsigned>(name->index) << 8 | name->sub);
    if (auto it = seen.find(key); it != seen.end()) {
      diag_.error(s.line, "[" + s.name + "] describes the same entry as the section at line " + std::to_string(it->second));
      continue;
    }
    seen.emplace(key, s.line);
    auto& obj = objects_[name->index];
    switch (name->kind) {
      case SectionName::Kind::Object: obj.main = &s; break;
      case SectionName::Kind::Sub:
        obj.subs[static_cast<std::uint8_t>(name->sub)] = &s;
        break;
      case SectionName::Kind::Name: obj.names = &s; break;
      case SectionName::Kind::Value: obj.values = &s; break;
      case SectionName::Kind::Ignored: break;
    }
  }
}

void Reader::cross_check() {
  for (const auto& [index, listing] : listed_) {
    auto it = objects_.find(index);
    if (it == objects_.end() || !it->second.main) {
      diag_.error(listing.line, hex_index(index) + " is listed in [" + list_name(listing.list) + "] but has no section [" +
                                    hex4(index) + "]");
    }
  }
  for (const auto& [index, secs] : objects_) {
    if (!secs.main) {
      for (const IniSection* s : {secs.subs.empty() ? nullptr : secs.subs.begin()->second, secs.names, secs.values}) {
        if (s) diag_.error(s->line, "[" + s->name + "] has no object section [" + hex4(index) + "]");
      }
      continue;
    }
    if (!listed_.count(index)) {
      // Tools that add objects by hand and forget the lists; the object is complete, so it is read.
      const bool mandatory = index == 0x1000 || index == 0x1001 || index == 0x1018;
      const bool manufacturer = index >= 0x2000 && index <= 0x5FFF;
      diag_.deviation(secs.main->line,
                      "[" + secs.main->name + "] is not listed in [MandatoryObjects], [OptionalObjects] or "
                      "[ManufacturerObjects]",
                      std::string("read as if listed in ") +
                          (mandatory ? "[MandatoryObjects]" : manufacturer ? "[ManufacturerObjects]" : "[OptionalObjects]"));
    }
  }
}

bool Reader::build_entry(std::uint16_t index, std::uint8_t sub, const std::string& name, const IniSection& s,
                         bool domain_object) {
  bool ok = true;
  DataType type = DataType::Domain;
  if (const auto* k = s.take("DATATYPE")) {
    std::string reason;
    const auto code = parse_count(k->value, 0xFFFF, reason);
    if (!code) {
      diag_.error(k->line, "DataType: " + reason);
      return false;
    }
    if (!is_known_type(static_cast<std::uint16_t>(*code))) {
      diag_.error(k->line, "unknown DataType " + hex_index(static_cast<unsigned>(*code)));
      return false;
    }
    type = static_cast<DataType>(*code);
  } else if (!domain_object) {
    diag_.error(s.line, "missing DataType in [" + s.name + "]");
    return false;
  }

  Access access = Access::ReadWrite;
  ProcessData process = ProcessData::None;
  if (const auto* k = s.take("ACCESSTYPE")) {
    const auto a = parse_access(k->value, process);
    if (!a) {
      diag_.error(k->line, "unknown AccessType '" + k->value + "' (ro, wo, rw, rwr, rww, const)");
      ok = false;
    } else {
      access = *a;
    }
  } else if (!domain_object) {
    diag_.error(s.line, "missing AccessType in [" + s.name + "]");
    ok = false;
  }

  bool mappable = false;
  if (const auto* k = s.take("PDOMAPPING")) {
    std::string reason;
    const auto v = parse_count(k->value, 1, reason);
    if (!v) {
      diag_.error(k->line, "PDOMapping must be 0 or 1");
      ok = false;
    } else {
      mappable = *v == 1;
      if (mappable && is_variable_length(type)) {
        diag_.warning(k->line, "PDOMapping=1 but a " + std::string(type_name(type)) + " cannot be mapped to a PDO");
      }
    }
  }

  ParsedValue def;
  def.bytes.assign(type_size(type), 0);
  int default_line = s.line;
  bool default_given = false;
  for (const char* key : {"DEFAULTVALUE", "PARAMETERVALUE"}) {  // a DCF's ParameterValue wins
    if (const auto* k = s.take(key)) {
      default_given = default_given || !k->value.empty();
      std::string reason;
      auto v = parse_value(type, without_c_suffix(type, k->value, k->line), true, reason);
      if (!v) {
        diag_.error(k->line, k->name + ": " + reason);
        ok = false;
      } else {
        def = std::move(*v);
        default_line = k->line;
      }
    }
  }

  std::optional<Bytes> limits[2];
  int limit_lines[2] = {0, 0};
  const char* limit_keys[2] = {"LOWLIMIT", "HIGHLIMIT"};
  for (int i = 0; i < 2; ++i) {
    const auto* k = s.take(limit_keys[i]);
    if (!k || k->value.empty()) continue;
    if (is_variable_length(type)) {
      diag_.warning(k->line, k->name + " has no meaning for a " + std::string(type_name(type)) + " and is ignored");
      continue;
    }
    std::string reason;
    auto v = parse_value(type, without_c_suffix(type, k->value, k->line), false, reason);
    if (!v) {
      diag_.error(k->line, k->name + ": " + reason);
      ok = false;
      continue;
    }
    limits[i] = std::move(v->bytes);
    limit_lines[i] = k->line;
  }
  if (limits[0] && limits[1] && compare_values(type, *limits[0], *limits[1]) > 0) {
    diag_.error(limit_lines[1], "HighLimit " + format_value(type, *limits[1], false) + " is below LowLimit " +
                                    format_value(type, *limits[0], false));
    ok = false;
  }

  for (const char* key : {"UPLOADFILE", "DOWNLOADFILE"}) {
    if (const auto* k = s.take(key)) diag_.warning(k->line, k->name + " is not supported: the DOMAIN starts empty");
  }
  (void)s.take("DENOTATION");  // DCF display name
  (void)s.take("OBJFLAGS");    // allowed in sub-index sections too; kept per object

  if (!ok) return false;
  OdEntry& e = od_.add_entry(index, sub, name, type, access, def.bytes, mappable);
  e.process_data = process;
  e.node_id_relative = def.node_relative;
  e.low_limit = limits[0];
  e.high_limit = limits[1];
  default_lines_[{index, sub}] = default_line;
  if (!default_given && !e.node_id_relative) {
    // No DefaultValue means 0, which the limits may exclude (typical of write-only commands).
    const bool below = e.low_limit && compare_values(type, e.default_value, *e.low_limit) < 0;
    const bool above = !below && e.high_limit && compare_values(type, e.default_value, *e.high_limit) > 0;
    if (below || above) {
      const Bytes& limit = below ? *e.low_limit : *e.high_limit;
      const std::string limit_text = std::string(below ? "LowLimit " : "HighLimit ") + format_value(type, limit, false);
      diag_.deviation(default_line, "no DefaultValue, and 0 is " + std::string(below ? "below " : "above ") + limit_text,
                      "the entry starts at " + limit_text);
      if (diag_.strict()) return true;
      e.default_value = limit;
      e.value = limit;
      return true;
    }
  }
  check_default_in_limits(e, default_line);
  return true;
}

std::string_view Reader::without_c_suffix(DataType type, std::string_view text, int line) {
  // C/C++ integer literal suffixes (U, L, UL, LL, ULL in any case and order) that code generators
  // copy into EDS values: CiA 306 integers have none. Strict, the deviation is the one error.
  if (!is_signed_integer(type) && !is_unsigned_integer(type)) return text;
  std::size_t end = text.size();
  while (end > 0 && (text[end - 1] == ' ' || text[end - 1] == '\t')) --end;
  std::size_t start = end;
  while (start > 0 && std::string_view("uUlL").find(text[start - 1]) != std::string_view::npos) --start;
  const std::size_t length = end - start;
  if (length == 0 || length > 3 || start == 0 || !std::isxdigit(static_cast<unsigned char>(text[start - 1]))) return text;
  std::string suffix(text.substr(start, length));
  for (char& c : suffix) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  static constexpr std::string_view kSuffixes[] = {"U", "L", "UL", "LU", "LL", "ULL", "LLU"};
  if (std::find(std::begin(kSuffixes), std::end(kSuffixes), suffix) == std::end(kSuffixes)) return text;
  const std::string_view number = text.substr(0, start);
  diag_.deviation(line, "C integer suffix '" + std::string(text.substr(start, length)) + "' in '" + std::string(text.substr(0, end)) + "'",
                  "read as " + std::string(number));
  return number;
}

void Reader::check_default_in_limits(const OdEntry& e, int line) {
  if (e.node_id_relative) return;  // the value depends on the node-ID
  const std::string value = format_value(e.type, e.default_value, false);
  if (e.low_limit && compare_values(e.type, e.default_value, *e.low_limit) < 0) {
    diag_.error(line, "DefaultValue " + value + " is below LowLimit " + format_value(e.type, *e.low_limit, false));
  } else if (e.high_limit && compare_values(e.type, e.default_value, *e.high_limit) > 0) {
    diag_.error(line, "DefaultValue " + value + " is above HighLimit " + format_value(e.type, *e.high_limit, false));
  }
}

void Reader::build_object(std::uint16_t index, const ObjectSections& secs) {
  const IniSection& s = *secs.main;
  std::string name;
  if (const auto* k = s.take("PARAMETERNAME")) {
    name = k->value;
    if (name.size() > kMaxNameLength) diag_.warning(k->line, "ParameterName longer than 241 characters");
  } else {
    diag_.error(s.line, "missing ParameterName in [" + s.name + "]");
  }
  ObjectCode code = ObjectCode::Var;  // CiA 306: a missing ObjectType means VAR
  if (const auto* k = s.take("OBJECTTYPE")) {
    std::string reason;
    const auto v = parse_count(k->value, 0xFF, reason);
    const std::set<std::uint64_t> known = {0x2, 0x5, 0x6, 0x7, 0x8, 0x9};
    if (!v) {
      diag_.error(k->line, "ObjectType: " + reason);
      failed_.insert(index);
      return;
    }
    if (!known.count(*v)) {
      failed_.insert(index);
      diag_.error(k->line, "unknown ObjectType 0x" + hex4(static_cast<unsigned>(*v)).substr(2) +
                               " (0x2 DOMAIN, 0x5 DEFTYPE, 0x6 DEFSTRUCT, 0x7 VAR, 0x8 ARRAY, 0x9 RECORD)");
      return;
    }
    code = static_cast<ObjectCode>(*v);
  }
  std::uint32_t flags = 0;
  if (const auto* k = s.take("OBJFLAGS")) {
    std::string reason;
    if (const auto v = parse_count(k->value, 0xFFFFFFFFu, reason)) {
      flags = static_cast<std::uint32_t>(*v);
    } else {
      diag_.error(k->line, "ObjFlags: " + reason);
    }
  }
  (void)s.take("DENOTATION");

  const bool single = code == ObjectCode::Var || code == ObjectCode::Domain || code == ObjectCode::DefType;
  const IniKey* subnumber = s.take("SUBNUMBER");
  const IniKey* compact = s.take("COMPACTSUBOBJ");
  if (single) {
    for (const IniKey* k : {subnumber, compact}) {
      if (k) diag_.error(k->line, k->name + " is not allowed for a " + code_name(code) + " object");
    }
    for (const auto& [sub, sec] : secs.subs) {
      diag_.error(sec->line, "[" + sec->name + "]: object [" + s.name + "] is a " + code_name(code) + " and has no sub-indices");
    }
    for (const IniSection* extra : {secs.names, secs.values}) {
      if (extra) diag_.error(extra->line, "[" + extra->name + "] needs CompactSubObj in [" + s.name + "]");
    }
    od_.add_object(index, name, code).obj_flags = flags;
    if (!build_entry(index, 0, name, s, code == ObjectCode::Domain)) {
      od_.remove_object(index);
      failed_.insert(index);
    }
    return;
  }

  std::uint64_t compact_count = 0;
  if (compact) {
    std::string reason;
    const auto v = parse_count(compact->value, 254, reason);
    if (!v) {
      diag_.error(compact->line, "CompactSubObj: " + reason);
      failed_.insert(index);
      return;
    }
    compact_count = *v;
  }
  if (compact_count > 0) {
    if (code == ObjectCode::Record) {
      // DCFs of a widely used stack describe the PDO mapping records (0x1600...) this way.
      std::string reading = "read as " + std::to_string(compact_count) + " sub-indices of the record's DataType, like an ARRAY";
      if (is_pdo_mapping(index)) reading += "; sub 0 (number of mapped objects) counts the leading non-zero entries";
      diag_.deviation(compact->line, "CompactSubObj is only allowed for ARRAY objects, and [" + s.name + "] is a RECORD", reading);
      if (diag_.strict()) {
        failed_.insert(index);
        return;
      }
    } else if (code != ObjectCode::Array) {
      diag_.error(compact->line, "CompactSubObj is only allowed for ARRAY objects");
      failed_.insert(index);
      return;
    }
    if (subnumber) {
      diag_.error(subnumber->line, "both SubNumber and CompactSubObj given in [" + s.name + "]");
      failed_.insert(index);
      return;
    }
    for (const auto& [sub, sec] : secs.subs) {
      diag_.error(sec->line, "[" + sec->name + "] conflicts with CompactSubObj in [" + s.name + "]");
    }
    if (!secs.subs.empty()) {
      failed_.insert(index);
      return;
    }
    od_.add_object(index, name, code).obj_flags = flags;
    build_compact_array(index, secs, name);
    if (code == ObjectCode::Record && is_pdo_mapping(index) && od_.entry(index, 1)) {
      // A mapping's sub 0 is the number of objects mapped, which masters write: not the ARRAY's
      // read-only count of sub-indices.
      OdEntry& count = *od_.entry(index, 0);
      std::uint8_t mapped = 0;
      while (mapped < compact_count && decode_unsigned(od_.entry(index, static_cast<std::uint8_t>(mapped + 1))->default_value) != 0)
        ++mapped;
      count.value = count.default_value = Bytes{mapped};
      count.access = od_.entry(index, 1)->access;
      count.name = "Number of mapped objects";
    }
    return;
  }

  // ARRAY, RECORD or DEFSTRUCT with explicit sub-index sections.
  for (const IniSection* extra : {secs.names, secs.values}) {
    if (extra) diag_.error(extra->line, "[" + extra->name + "] needs CompactSubObj in [" + s.name + "]");
  }
  for (const char* key : {"DATATYPE", "ACCESSTYPE", "DEFAULTVALUE", "PDOMAPPING", "LOWLIMIT", "HIGHLIMIT"}) {
    if (const auto* k = s.take(key)) {
      diag_.warning(k->line, k->name + " has no meaning for an " + code_name(code) + " without CompactSubObj and is ignored");
    }
  }
  if (!subnumber) {
    diag_.error(s.line, "missing SubNumber in [" + s.name + "]");
  } else {
    std::string reason;
    const auto v = parse_count(subnumber->value, 255, reason);
    if (!v) {
      diag_.error(subnumber->line, "SubNumber: " + reason);
    } else if (*v > secs.subs.size()) {
      diag_.deviation(subnumber->line,
                      "SubNumber=" + std::to_string(*v) + " but [" + s.name + "] has " + std::to_string(secs.subs.size()) +
                          " sub-index sections",
                      "the " + std::to_string(secs.subs.size()) + " sections given are read");
    } else if (*v != secs.subs.size()) {
      diag_.error(subnumber->line, "SubNumber=" + std::to_string(*v) + " but [" + s.name + "] has " +
                                       std::to_string(secs.subs.size()) + " sub-index sections");
    }
  }
  const unsigned highest = secs.subs.empty() ? 0u : secs.subs.rbegin()->first;
  const bool add_sub0 = !secs.subs.count(0);
  if (add_sub0) {
    diag_.deviation(s.line, "missing [" + hex4(index) + "sub0] (highest sub-index supported)",
                    "sub 0 is UNSIGNED8, ro, " + std::to_string(highest) + " (the highest sub-index given)");
  }
  od_.add_object(index, name, code).obj_flags = flags;
  build_record(index, secs);
  if (add_sub0 && !diag_.strict()) {
    od_.add_entry(index, 0, "Highest sub-index supported", DataType::Unsigned8, Access::ReadOnly,
                  Bytes{static_cast<std::uint8_t>(highest)});
  }
}

void Reader::build_record(std::uint16_t index, const ObjectSections& secs) {
  for (const auto& [sub, sec] : secs.subs) {
    std::string name;
    if (const auto* k = sec->take("PARAMETERNAME")) {
      name = k->value;
      if (name.size() > kMaxNameLength) diag_.warning(k->line, "ParameterName longer than 241 characters");
    } else {
      diag_.error(sec->line, "missing ParameterName in [" + sec->name + "]");
    }
    if (const auto* k = sec->take("OBJECTTYPE")) {
      std::string reason;
      const auto v = parse_count(k->value, 0xFF, reason);
      if (!v || *v != 0x7) diag_.error(k->line, "a sub-index must have ObjectType 0x7 (VAR)");
    }
    for (const char* key : {"SUBNUMBER", "COMPACTSUBOBJ"}) {
      if (const auto* k = sec->take(key)) diag_.error(k->line, k->name + " is not allowed in a sub-index section");
    }
    if (!build_entry(index, sub, name, *sec, false)) failed_.insert(index);
  }
  if (const auto* sub0 = od_.entry(index, 0); sub0 && sub0->type != DataType::Unsigned8) {
    diag_.warning(secs.subs.at(0)->line, "sub-index 0 of " + hex_index(index) + " should be UNSIGNED8 (CiA 301)");
  }
}

void Reader::build_compact_array(std::uint16_t index, const ObjectSections& secs, const std::string& name) {
  const IniSection& s = *secs.main;
  std::string reason;
  const auto count = static_cast<unsigned>(*parse_count(s.find("COMPACTSUBOBJ")->value, 254, reason));
  // CiA 306 compact form: sub 0 is the UNSIGNED8 count; subs 1..N share the object's keys and
  // are named "<ParameterName><sub-index>" unless [xxxxName] says otherwise.
  od_.add_entry(index, 0, "NrOfObjects", DataType::Unsigned8, Access::ReadOnly, Bytes{static_cast<std::uint8_t>(count)});
  default_lines_[{index, 0}] = s.find("COMPACTSUBOBJ")->line;
  if (!build_entry(index, 1, name + "1", s, false)) {
    od_.remove_object(index);
    failed_.insert(index);
    return;
  }
  for (unsigned sub = 2; sub <= count; ++sub) {
    OdEntry copy = *od_.entry(index, 1);
    copy.sub = static_cast<std::uint8_t>(sub);
    copy.name = name + std::to_string(sub);
    od_.add_entry(std::move(copy));
    default_lines_[{index, static_cast<std::uint8_t>(sub)}] = default_lines_[{index, 1}];
  }
  if (secs.names) apply_names(index, *secs.names, count);
  if (secs.values) apply_values(index, *secs.values, count);
}

void Reader::apply_names(std::uint16_t index, const IniSection& s, unsigned count) {
  const auto* nr = s.take("NROFENTRIES");
  if (!nr) {
    diag_.error(s.line, "missing NrOfEntries in [" + s.name + "]");
    return;
  }
  std::string reason;
  const auto n = parse_count(nr->value, 254, reason);
  if (!n) {
    diag_.error(nr->line, "NrOfEntries: " + reason);
    return;
  }
  unsigned given = 0;
  for (std::size_t i = 0; i < s.keys.size(); ++i) {
    const IniKey& k = s.keys[i];
    if (k.upper == "NROFENTRIES") continue;
    s.used[i] = true;
    const auto sub = parse_count(k.name, 254, reason);
    if (!sub || *sub == 0 || *sub > count) {
      diag_.error(k.line, "'" + k.name + "' is not a sub-index of " + hex_index(index) + " (1.." + std::to_string(count) + ")");
      continue;
    }
    ++given;
    if (auto* e = od_.entry(index, static_cast<std::uint8_t>(*sub))) e->name = k.value;
  }
  if (given != *n) {
    diag_.error(nr->line, "NrOfEntries=" + std::to_string(*n) + " but [" + s.name + "] gives " + std::to_string(given));
  }
}

void Reader::apply_values(std::uint16_t index, const IniSection& s, unsigned count) {
  const auto* nr = s.take("NROFENTRIES");
  if (!nr) {
    diag_.error(s.line, "missing NrOfEntries in [" + s.name + "]");
    return;
  }
  std::string reason;
  const auto n = parse_count(nr->value, 254, reason);
  if (!n) {
    diag_.error(nr->line, "NrOfEntries: " + reason);
    return;
  }
  unsigned given = 0;
  for (std::size_t i = 0; i < s.keys.size(); ++i) {
    const IniKey& k = s.keys[i];
    if (k.upper == "NROFENTRIES") continue;
    s.used[i] = true;
    const auto sub = parse_count(k.name, 254, reason);
    if (!sub || *sub == 0 || *sub > count) {
      diag_.error(k.line, "'" + k.name + "' is not a sub-index of " + hex_index(index) + " (1.." + std::to_string(count) + ")");
      continue;
    }
    ++given;
    OdEntry* e = od_.entry(index, static_cast<std::uint8_t>(*sub));
    if (!e) continue;
    auto v = parse_value(e->type, without_c_suffix(e->type, k.value, k.line), true, reason);
    if (!v) {
      diag_.error(k.line, "value of sub-index " + k.name + ": " + reason);
      continue;
    }
    e->default_value = v->bytes;
    e->value = std::move(v->bytes);
    e->node_id_relative = v->node_relative;
    default_lines_[{index, e->sub}] = k.line;
    check_default_in_limits(*e, k.line);
  }
  if (given != *n) {
    diag_.error(nr->line, "NrOfEntries=" + std::to_string(*n) + " but [" + s.name + "] gives " + std::to_string(given));
  }
}

// ---- whole-dictionary checks and implicit objects -------------------------------------------------

void Reader::check_mandatory() {
  const IniSection* list = ini_.find("MANDATORYOBJECTS");
  if (!list || mandatory_list_broken_) return;  // already reported
  for (std::uint16_t index : {0x1000, 0x1001, 0x1018}) {
    if (listed_.count(index)) continue;
    if (auto it = objects_.find(index); it != objects_.end() && it->second.main) continue;  // present, unlisted: cross_check
    const std::string reason = "mandatory object " + hex_index(index) + " missing (CiA 306: 0x1000, 0x1001, 0x1018)";
    if (index == 0x1018 || objects_.count(index)) {
      diag_.error(list->line, reason);
      continue;
    }
    if (index == 0x1000) {
      // Every CiA 301 device has a device type; 0 is "no standardised device profile".
      diag_.deviation(list->line, reason, "0x1000 is UNSIGNED32, ro, 0x00000000 (no device profile)");
      if (!diag_.strict()) od_.add_var(0x1000, "Device type", DataType::Unsigned32, Access::ReadOnly, Bytes{0, 0, 0, 0});
    } else {
      // Every CiA 301 device has an error register; the node's EMCY service sets its bits.
      diag_.deviation(list->line, reason, "0x1001 is UNSIGNED8, ro, 0 (the error register the node's EMCY service keeps)");
      if (!diag_.strict()) od_.add_var(0x1001, "Error register", DataType::Unsigned8, Access::ReadOnly, Bytes{0});
    }
  }
}

void Reader::add_dummy_objects() {
  // CiA 301 §7.4.7.1: a supported dummy type is a data type entry of the dictionary; its value
  // (read access) is the type's length in bits.
  for (unsigned t = 1; t <= 7; ++t) {
    if (!(dummy_mask_ & (1u << t)) || od_.object(static_cast<std::uint16_t>(t))) continue;
    const auto type = static_cast<DataType>(t);
    const auto index = static_cast<std::uint16_t>(t);
    const std::string name(type_name(type));
    od_.add_object(index, name, ObjectCode::DefType);
    const std::uint32_t bits = type == DataType::Boolean ? 1u : static_cast<std::uint32_t>(type_size(type) * 8);
    od_.add_entry(index, 0, name, DataType::Unsigned32, Access::Const, ObjectDictionary::encode(DataType::Unsigned32, bits))
        .persistent = false;
  }
}

void Reader::build_compact_pdo(std::uint16_t comm, std::uint16_t map, int number, bool receive) {
  // CompactPDO (CiA 306 §4.5): the bits say which communication sub-indices exist; values are
  // the pre-defined connection set COB-IDs for PDO 1-4 (others invalid) and 0 elsewhere, and the
  // mapping object has 64 empty entries — the same as lely-core's reader.
  const unsigned mask = info_.compact_pdo & 0x3F;
  if (!od_.object(comm)) {
    unsigned highest = 0;
    for (unsigned i = 0; i < 6; ++i)
      if (mask & (1u << i)) highest = i + 1;
    od_.add_object(comm, receive ? "RPDO communication parameter" : "TPDO communication parameter", ObjectCode::Record);
    od_.add_entry(comm, 0, "Highest sub-index supported", DataType::Unsigned8, Access::Const,
                  Bytes{static_cast<std::uint8_t>(highest)});
    if (mask & 0x01) {
      const bool predefined = number <= 4;
      const std::uint32_t base = static_cast<std::uint32_t>(receive ? 0x200 : 0x180) + 0x100u * static_cast<std::uint32_t>(number - 1);
      auto& cob = od_.add_entry(comm, 1, receive ? "COB-ID used by RPDO" : "COB-ID used by TPDO", DataType::Unsigned32,
                                Access::ReadWrite, ObjectDictionary::encode(DataType::Unsigned32, predefined ? base : 0x80000000u));
      cob.node_id_relative = predefined;
    }
    if (mask & 0x02) od_.add_entry(comm, 2, "Transmission type", DataType::Unsigned8, Access::ReadWrite, Bytes{0});
    if (mask & 0x04) od_.add_entry(comm, 3, "Inhibit time", DataType::Unsigned16, Access::ReadWrite, Bytes{0, 0});
    if (mask & 0x08) od_.add_entry(comm, 4, receive ? "Compatibility entry" : "Reserved", DataType::Unsigned8, Access::ReadWrite, Bytes{0});
    if (mask & 0x10) od_.add_entry(comm, 5, "Event timer", DataType::Unsigned16, Access::ReadWrite, Bytes{0, 0});
    if (mask & 0x20) od_.add_entry(comm, 6, "SYNC start value", DataType::Unsigned8, Access::ReadWrite, Bytes{0});
  }
  if (!od_.object(map)) {
    od_.add_object(map, receive ? "RPDO mapping parameter" : "TPDO mapping parameter", ObjectCode::Record);
    od_.add_entry(map, 0, "Highest sub-index supported", DataType::Unsigned8, Access::ReadWrite, Bytes{0});
    for (unsigned i = 1; i <= 0x40; ++i) {
      od_.add_entry(map, static_cast<std::uint8_t>(i), "Application object " + std::to_string(i), DataType::Unsigned32,
                    Access::ReadWrite, Bytes{0, 0, 0, 0});
    }
  }
}

void Reader::add_compact_pdos() {
  if (info_.compact_pdo == 0) return;
  for (bool receive : {true, false}) {
    const std::uint16_t comm_base = receive ? 0x1400 : 0x1800, map_base = receive ? 0x1600 : 0x1A00;
    int implicit = receive ? info_.nr_of_rx_pdo : info_.nr_of_tx_pdo;
    for (int i = 0; i < 512 && implicit > 0; ++i) {
      if (od_.object(static_cast<std::uint16_t>(comm_base + i)) || od_.object(static_cast<std::uint16_t>(map_base + i))) --implicit;
    }
    for (int i = 0; i < 512; ++i) {
      const auto comm = static_cast<std::uint16_t>(comm_base + i), map = static_cast<std::uint16_t>(map_base + i);
      if (!od_.object(comm) && !od_.object(map)) {
        if (implicit <= 0) continue;
        --implicit;
      }
      build_compact_pdo(comm, map, i + 1, receive);
    }
  }
}

void Reader::check_pdo_counts() {
  const IniSection* s = ini_.find("DEVICEINFO");
  if (!s) return;
  for (bool receive : {true, false}) {
    const auto* k = s->find(receive ? "NROFRXPDO" : "NROFTXPDO");
    std::string reason;
    if (!k || !parse_count(k->value, 512, reason)) continue;  // a bad value was reported where it was read
    const std::uint16_t base = receive ? 0x1400 : 0x1800;
    unsigned count = 0;
    for (unsigned i = 0; i < 512; ++i)
      if (od_.object(static_cast<std::uint16_t>(base + i))) ++count;
    const unsigned declared = receive ? info_.nr_of_rx_pdo : info_.nr_of_tx_pdo;
    if (count != declared) {
      diag_.warning(k->line, k->name + "=" + std::to_string(declared) + " but the file describes " + std::to_string(count) +
                                 (receive ? " RPDOs" : " TPDOs"));
    }
  }
}

void Reader::check_cob_ids() {
  // CiA 301 §7.5.2 (0x1005, 0x1012, 0x1014, 0x1200-0x12FF, 0x1400-0x15FF, 0x1800-0x19FF): with
  // bit 29 clear the CAN-ID has 11 bits, so bits 11-28 must be 0; such a COB-ID matches no frame
  // (an SDO download of it aborts 06090030h). Checked for every node-ID a "$NODEID+" value can take.
  for (const auto& [index, obj] : od_.objects()) {
    const bool services = index == 0x1005 || index == 0x1012 || index == 0x1014;
    const bool channel = (index >= 0x1200 && index <= 0x12FF) || (index >= 0x1400 && index <= 0x15FF) ||
                         (index >= 0x1800 && index <= 0x19FF);
    if (!services && !channel) continue;
    for (const auto& [sub, e] : obj.entries) {
      const bool cob_entry = services ? sub == 0 : (sub == 1 || (sub == 2 && index < 0x1300));
      if (!cob_entry || type_size(e.type) != 4) continue;
      const std::uint64_t base = decode_unsigned(e.default_value);
      const int line = default_lines_.count({index, sub}) ? default_lines_.at({index, sub}) : 0;
      const std::string where = hex_index(index) + " sub " + std::to_string(sub) + ": COB-ID " +
                                (e.node_id_relative ? "$NODEID+" : "") + format_value(DataType::Unsigned32, e.default_value, false);
      for (unsigned id = e.node_id_relative ? 1 : 0; id <= (e.node_id_relative ? 127u : 0u); ++id) {
        const std::uint64_t v = base + id;
        const std::string with_id = e.node_id_relative ? " with node-ID " + std::to_string(id) : "";
        if (v > 0xFFFFFFFFu) {
          diag_.error(line, where + with_id + " overflows 32 bits");
          break;
        }
        const bool invalid_flag = !services && (v & 0x80000000u);  // "not valid": the CAN-ID is unused
        if (!invalid_flag && !(v & 0x20000000u) && (v & 0x1FFFF800u)) {
          diag_.error(line, where + with_id + " has CAN-ID bits above 0x7FF without bit 29 (29-bit CAN-ID) set");
          break;
        }
      }
    }
  }
}

void Reader::check_identity() {
  const IniSection* s = ini_.find("DEVICEINFO");
  if (!s) return;
  const std::tuple<const char*, std::uint8_t, std::uint32_t> keys[] = {
      {"VENDORNUMBER", 1, info_.vendor_number}, {"PRODUCTNUMBER", 2, info_.product_number}, {"REVISIONNUMBER", 3, info_.revision_number}};
  for (const auto& [key, sub, value] : keys) {
    const auto* k = s->find(key);
    const OdEntry* e = od_.entry(0x1018, sub);
    if (!k || !e || e->node_id_relative) continue;
    const auto reported = static_cast<std::uint32_t>(decode_unsigned(e->default_value));
    if (reported != value) {
      diag_.warning(k->line, k->name + " " + format_value(DataType::Unsigned32, ObjectDictionary::encode(DataType::Unsigned32, value), false) +
                                 " differs from 0x1018 sub " + std::to_string(sub) + " (" +
                                 format_value(DataType::Unsigned32, e->default_value, false) + ")");
    }
  }
}

void Reader::check_default_mappings() {
  for (bool receive : {true, false}) {
    const std::uint16_t base = receive ? 0x1600 : 0x1A00;
    for (unsigned i = 0; i < 512; ++i) {
      const auto map = static_cast<std::uint16_t>(base + i);
      const OdObject* obj = od_.object(map);
      const OdEntry* count = od_.entry(map, 0);
      if (!obj || !count) continue;
      const unsigned n = static_cast<unsigned>(decode_unsigned(count->default_value));
      unsigned bits_total = 0;
      for (unsigned sub = 1; sub <= n; ++sub) {
        const OdEntry* m = od_.entry(map, static_cast<std::uint8_t>(sub));
        const int line = default_lines_.count({map, 0}) ? default_lines_.at({map, 0}) : 0;
        if (!m) {
          diag_.warning(line, hex_index(map) + " maps " + std::to_string(n) + " objects but has no sub-index " + std::to_string(sub));
          break;
        }
        const int at = default_lines_.count({map, m->sub}) ? default_lines_.at({map, m->sub}) : line;
        const auto v = static_cast<std::uint32_t>(decode_unsigned(m->default_value));
        const auto target = static_cast<std::uint16_t>(v >> 16);
        const auto target_sub = static_cast<std::uint8_t>(v >> 8);
        const unsigned bits = v & 0xFF;
        const std::string what = "default mapping " + format_value(DataType::Unsigned32, m->default_value, false) + ": ";
        bits_total += bits;
        if (bits == 0 || bits % 8 != 0) {
          diag_.warning(at, what + "length " + std::to_string(bits) + " is not a whole number of bytes");
          continue;
        }
        if (target >= 1 && target <= 7 && target_sub == 0) {
          if (!receive || !(info_.dummy_usage & (1u << target))) {
            diag_.warning(at, what + "dummy " + hex_index(target) + (receive ? " is not enabled in [DummyUsage]" : " in a TPDO"));
          } else if (type_size(static_cast<DataType>(target)) * 8 != bits) {
            diag_.warning(at, what + "length differs from the dummy's type");
          }
          continue;
        }
        const OdEntry* e = od_.entry(target, target_sub);
        const std::string name = hex_index(target) + " sub " + std::to_string(target_sub);
        if (!e) {
          diag_.warning(at, what + name + " does not exist");
        } else if (!e->pdo_mappable) {
          diag_.warning(at, what + name + " is not PDO-mappable");
        } else if (receive ? !e->writable() : !e->readable()) {
          diag_.warning(at, what + name + (receive ? " is not writable" : " is not readable"));
        } else if (e->bit_length() != bits) {
          diag_.warning(at, what + name + " is " + std::to_string(e->bit_length()) + " bits long");
        }
      }
      if (bits_total > 64) {
        const int line = default_lines_.count({map, 0}) ? default_lines_.at({map, 0}) : 0;
        diag_.warning(line, hex_index(map) + ": the default mapping is " + std::to_string(bits_total) + " bits long (at most 64)");
      }
    }
  }
}

void Reader::warn_unknown_keys() {
  for (const IniSection* s : used_sections_) {
    if (auto it = section_index_.find(s); it != section_index_.end() && failed_.count(it->second)) continue;
    for (std::size_t i = 0; i < s->keys.size(); ++i) {
      if (!s->used[i]) diag_.warning(s->keys[i].line, "unknown key '" + s->keys[i].name + "' in [" + s->name + "] ignored");
    }
  }
}

std::optional<ObjectDictionary> Reader::run() {
  read_file_info();
  read_device_info();
  read_dummy_usage();
  read_comments();
  read_lists();
  collect_sections();
  cross_check();
  for (const auto& [index, secs] : objects_) {
    if (secs.main) build_object(index, secs);
  }
  check_mandatory();
  add_dummy_objects();
  add_compact_pdos();
  check_pdo_counts();
  check_cob_ids();
  check_identity();
  check_default_mappings();
  warn_unknown_keys();
  if (diag_.has_errors()) return std::nullopt;
  return std::move(od_);
}

}  // namespace

std::optional<ObjectDictionary> read_eds(std::string_view text, Diagnostics& diag, EdsFileInfo& info) {
  const IniFile ini = lex_ini(text, diag);
  Reader reader(ini, diag, info);
  return reader.run();
}

}  // namespace canopen::eds_detail
