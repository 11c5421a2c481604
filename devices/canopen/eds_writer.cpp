// write_eds(): an object dictionary as a CiA 306 EDS. Every object is described explicitly (no
// compact forms), in index order, so the text depends on nothing but the dictionary and the info.
#include <string>

#include "devices/canopen/eds.h"
#include "devices/canopen/eds_value.h"

namespace canopen {

namespace {

using eds_detail::format_value;

std::string hex(std::uint64_t v, int width) {
  static constexpr char kDigits[] = "0123456789ABCDEF";
  std::string out;
  do {
    out.insert(out.begin(), kDigits[v & 0xF]);
    v >>= 4;
  } while (v != 0);
  while (static_cast<int>(out.size()) < width) out.insert(out.begin(), '0');
  return out;
}

class Writer {
 public:
  void section(const std::string& name) {
    if (!out_.empty()) out_ += '\n';
    out_ += '[' + name + "]\n";
  }
  void key(std::string_view k, std::string_view v) {
    out_.append(k);
    out_ += '=';
    out_.append(v);
    out_ += '\n';
  }
  void key(std::string_view k, std::uint64_t v) { key(k, std::to_string(v)); }
  std::string take() { return std::move(out_); }

 private:
  std::string out_;
};

const char* access_text(const OdEntry& e) {
  switch (e.access) {
    case Access::ReadOnly: return "ro";
    case Access::WriteOnly: return "wo";
    case Access::Const: return "const";
    case Access::ReadWrite:
      if (e.process_data == ProcessData::Input) return "rwr";
      if (e.process_data == ProcessData::Output) return "rww";
      return "rw";
  }
  return "rw";
}

// DEFTYPE objects 0x0001-0x0007 are the supported dummy types: [DummyUsage], not sections.
bool is_dummy_object(const OdObject& o) { return o.code == ObjectCode::DefType && o.index >= 1 && o.index <= 7; }

bool is_written(const OdObject& o) { return !o.entries.empty() && o.code != ObjectCode::Null && !is_dummy_object(o); }

bool single_entry(ObjectCode c) { return c == ObjectCode::Var || c == ObjectCode::Domain || c == ObjectCode::DefType; }

// A DCF states the value the node holds (node-relative ones resolved); not for entries a master
// cannot read back (write-only) or that have no fixed value (DOMAIN).
bool has_parameter_value(const OdEntry& e) { return e.access != Access::WriteOnly && e.type != DataType::Domain; }

void write_entry_keys(Writer& w, const OdEntry& e, bool dcf) {
  w.key("DataType", "0x" + hex(static_cast<std::uint16_t>(e.type), 4));
  w.key("AccessType", access_text(e));
  w.key("DefaultValue", format_value(e.type, e.default_value, e.node_id_relative));
  if (dcf && has_parameter_value(e)) w.key("ParameterValue", format_value(e.type, e.value, false));
  w.key("PDOMapping", e.pdo_mappable ? 1 : 0);
  if (e.low_limit) w.key("LowLimit", format_value(e.type, *e.low_limit, false));
  if (e.high_limit) w.key("HighLimit", format_value(e.type, *e.high_limit, false));
}

void write_object(Writer& w, const OdObject& o, bool dcf) {
  const std::string index = hex(o.index, 4);
  w.section(index);
  const OdEntry& first = o.entries.begin()->second;
  w.key("ParameterName", o.name.empty() ? first.name : o.name);
  w.key("ObjectType", "0x" + hex(static_cast<unsigned>(o.code), 1));
  if (single_entry(o.code)) {
    if (o.obj_flags != 0) w.key("ObjFlags", "0x" + hex(o.obj_flags, 8));
    write_entry_keys(w, first, dcf);
    return;
  }
  w.key("SubNumber", o.entries.size());
  if (o.obj_flags != 0) w.key("ObjFlags", "0x" + hex(o.obj_flags, 8));
  for (const auto& [sub, e] : o.entries) {
    w.section(index + "sub" + hex(sub, 1));
    w.key("ParameterName", e.name);
    w.key("ObjectType", "0x7");
    write_entry_keys(w, e, dcf);
  }
}

std::uint32_t identity(const ObjectDictionary& od, std::uint8_t sub, std::uint32_t fallback) {
  const OdEntry* e = od.entry(0x1018, sub);
  if (!e || e->node_id_relative || type_size(e->type) == 0) return fallback;
  return static_cast<std::uint32_t>(decode_unsigned(e->default_value));
}

unsigned count_objects(const ObjectDictionary& od, std::uint16_t first, std::uint16_t last) {
  unsigned n = 0;
  for (auto it = od.objects().lower_bound(first); it != od.objects().end() && it->first <= last; ++it) ++n;
  return n;
}

std::string write_file(const ObjectDictionary& od, const EdsFileInfo& info, const DcfCommissioning* dcf) {
  Writer w;
  w.section("FileInfo");
  w.key("FileName", info.file_name);
  w.key("FileVersion", info.file_version);
  w.key("FileRevision", info.file_revision);
  w.key("EDSVersion", info.eds_version.empty() ? "4.0" : info.eds_version);
  w.key("Description", info.description);
  w.key("CreationTime", info.creation_time);
  w.key("CreationDate", info.creation_date);
  w.key("CreatedBy", info.created_by);
  if (!info.modification_time.empty()) w.key("ModificationTime", info.modification_time);
  if (!info.modification_date.empty()) w.key("ModificationDate", info.modification_date);
  if (!info.modified_by.empty()) w.key("ModifiedBy", info.modified_by);

  w.section("DeviceInfo");
  w.key("VendorName", info.vendor_name);
  w.key("VendorNumber", "0x" + hex(identity(od, 1, info.vendor_number), 8));
  w.key("ProductName", info.product_name);
  w.key("ProductNumber", "0x" + hex(identity(od, 2, info.product_number), 8));
  w.key("RevisionNumber", "0x" + hex(identity(od, 3, info.revision_number), 8));
  w.key("OrderCode", info.order_code);
  for (unsigned rate : {10u, 20u, 50u, 125u, 250u, 500u, 800u, 1000u}) {
    bool supported = false;
    for (unsigned r : info.baud_rates_kbit) supported = supported || r == rate;
    w.key("BaudRate_" + std::to_string(rate), supported ? 1 : 0);
  }
  w.key("SimpleBootUpMaster", info.simple_boot_up_master ? 1 : 0);
  w.key("SimpleBootUpSlave", info.simple_boot_up_slave ? 1 : 0);
  w.key("Granularity", info.granularity);
  w.key("DynamicChannelsSupported", info.dynamic_channels ? 1 : 0);
  w.key("CompactPDO", 0);
  w.key("GroupMessaging", info.group_messaging ? 1 : 0);
  w.key("NrOfRXPDO", count_objects(od, 0x1400, 0x15FF));
  w.key("NrOfTXPDO", count_objects(od, 0x1800, 0x19FF));
  w.key("LSS_Supported", info.lss_supported ? 1 : 0);

  if (dcf) {
    w.section("DeviceComissioning");  // CiA 306's spelling
    w.key("NodeID", "0x" + hex(dcf->node_id, 2));
    w.key("NodeName", dcf->node_name);
    if (dcf->baudrate_kbit != 0) w.key("Baudrate", dcf->baudrate_kbit);
    w.key("NetNumber", dcf->net_number);
    w.key("NetworkName", dcf->network_name);
    w.key("CANopenManager", 0);
    w.key("LSS_SerialNumber", identity(od, 4, 0));
  }

  w.section("DummyUsage");
  for (unsigned t = 1; t <= 7; ++t) {
    const OdObject* o = od.object(static_cast<std::uint16_t>(t));
    const bool used = (info.dummy_usage & (1u << t)) || (o && is_dummy_object(*o));
    w.key("Dummy000" + std::to_string(t), used ? 1 : 0);
  }

  if (!info.comments.empty()) {
    w.section("Comments");
    w.key("Lines", info.comments.size());
    for (std::size_t i = 0; i < info.comments.size(); ++i) w.key("Line" + std::to_string(i + 1), info.comments[i]);
  }

  enum class List { Mandatory, Optional, Manufacturer };
  const auto list_of = [](std::uint16_t index) {
    if (index == 0x1000 || index == 0x1001 || index == 0x1018) return List::Mandatory;
    if (index >= 0x2000 && index <= 0x5FFF) return List::Manufacturer;
    return List::Optional;
  };
  for (auto [list, name] : {std::pair{List::Mandatory, "MandatoryObjects"}, std::pair{List::Optional, "OptionalObjects"},
                            std::pair{List::Manufacturer, "ManufacturerObjects"}}) {
    std::vector<const OdObject*> members;
    for (const auto& [index, o] : od.objects())
      if (is_written(o) && list_of(index) == list) members.push_back(&o);
    w.section(name);
    w.key("SupportedObjects", members.size());
    for (std::size_t i = 0; i < members.size(); ++i) w.key(std::to_string(i + 1), "0x" + hex(members[i]->index, 4));
    for (const OdObject* o : members) write_object(w, *o, dcf != nullptr);
  }
  return w.take();
}

}  // namespace

std::string write_eds(const ObjectDictionary& od, const EdsFileInfo& info) { return write_file(od, info, nullptr); }

std::string write_dcf(const ObjectDictionary& od, const EdsFileInfo& info, const DcfCommissioning& commissioning) {
  return write_file(od, info, &commissioning);
}

}  // namespace canopen
