#include "devices/canopen/eds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>

#include "tests/devices/canopen/generic_node.h"

using canopen::Access;
using canopen::Bytes;
using canopen::DataType;
using canopen::EdsError;
using canopen::EdsFileInfo;
using canopen::ObjectCode;
using canopen::ObjectDictionary;
using canopen::ProcessData;

namespace {

const std::string kDataDir = VPLANT_TEST_DATA_DIR "/eds/";

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// 1-based number of the (single) line whose trimmed text is `needle`.
int line_of(const std::string& text, const std::string& needle) {
  std::istringstream in(text);
  std::string line;
  int n = 0, found = 0;
  while (std::getline(in, line)) {
    ++n;
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    if (line == needle) {
      EXPECT_EQ(found, 0) << "needle '" << needle << "' is not unique";
      found = n;
    }
  }
  EXPECT_NE(found, 0) << "needle '" << needle << "' not found";
  return found;
}

// `text` with the single occurrence of `from` replaced by `to`.
std::string with(std::string text, const std::string& from, const std::string& to) {
  const auto pos = text.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  EXPECT_EQ(text.find(from, pos + 1), std::string::npos) << "'" << from << "' is not unique";
  if (pos != std::string::npos) text.replace(pos, from.size(), to);
  return text;
}

// A small, clean EDS that the error tests break one way at a time.
const std::string kMinimal = R"([FileInfo]
FileName=minimal.eds
FileVersion=1
FileRevision=0
EDSVersion=4.0
Description=minimal test device
CreationTime=12:00AM
CreationDate=01-01-2026
CreatedBy=test

[DeviceInfo]
VendorName=test
VendorNumber=0x00000001
ProductName=minimal
ProductNumber=0x00000002
RevisionNumber=0x00000003
OrderCode=M1
BaudRate_10=0
BaudRate_20=0
BaudRate_50=0
BaudRate_125=1
BaudRate_250=1
BaudRate_500=1
BaudRate_800=0
BaudRate_1000=1
SimpleBootUpMaster=0
SimpleBootUpSlave=1
Granularity=8
DynamicChannelsSupported=0
GroupMessaging=0
NrOfRXPDO=0
NrOfTXPDO=0
LSS_Supported=0

[DummyUsage]
Dummy0001=0
Dummy0002=0
Dummy0003=0
Dummy0004=0
Dummy0005=1
Dummy0006=0
Dummy0007=0

[MandatoryObjects]
SupportedObjects=3
1=0x1000
2=0x1001
3=0x1018

[1000]
ParameterName=Device type
ObjectType=0x7
DataType=0x0007
AccessType=ro
DefaultValue=0x00000191
PDOMapping=0

[1001]
ParameterName=Error register
ObjectType=0x7
DataType=0x0005
AccessType=ro
DefaultValue=0
PDOMapping=0

[1018]
ParameterName=Identity object
ObjectType=0x9
SubNumber=4

[1018sub0]
ParameterName=Highest sub-index supported
ObjectType=0x7
DataType=0x0005
AccessType=ro
DefaultValue=3
PDOMapping=0

[1018sub1]
ParameterName=Vendor-ID
ObjectType=0x7
DataType=0x0007
AccessType=ro
DefaultValue=0x00000001
PDOMapping=0

[1018sub2]
ParameterName=Product code
ObjectType=0x7
DataType=0x0007
AccessType=ro
DefaultValue=0x00000002
PDOMapping=0

[1018sub3]
ParameterName=Revision number
ObjectType=0x7
DataType=0x0007
AccessType=ro
DefaultValue=0x00000003
PDOMapping=0

[ManufacturerObjects]
SupportedObjects=1
1=0x2000

[2000]
ParameterName=Setpoint
ObjectType=0x7
DataType=0x0005
AccessType=rw
DefaultValue=7
PDOMapping=0
)";

// kMinimal with a second manufacturer object 0x2001 (listed) described by `body`.
std::string minimal_with_2001(const std::string& body) {
  std::string t = kMinimal;
  t = with(t, "SupportedObjects=1\n1=0x2000\n", "SupportedObjects=2\n1=0x2000\n2=0x2001\n");
  return t + "\n" + body;
}

// Strict: the deviations that are otherwise loaded with a warning are errors too.
void expect_error(const std::string& text, const std::string& at_line, const std::string& reason) {
  EdsError error;
  auto od = canopen::parse_eds(text, "bad.eds", error, nullptr, nullptr, canopen::EdsStrictness::Strict);
  EXPECT_FALSE(od.has_value());
  const int line = line_of(text, at_line);
  EXPECT_EQ(error.mark.file, "bad.eds");
  EXPECT_EQ(error.mark.line, line);
  EXPECT_FALSE(error.warning);
  EXPECT_EQ(error.to_string(), "bad.eds:" + std::to_string(line) + ": " + reason);
}

std::vector<EdsError> warnings_of(const std::string& text) {
  EdsError error;
  std::vector<EdsError> warnings;
  auto od = canopen::parse_eds(text, "w.eds", error, nullptr, &warnings);
  EXPECT_TRUE(od.has_value()) << error.to_string();
  return warnings;
}

void expect_warning(const std::string& text, const std::string& at_line, const std::string& reason) {
  const auto warnings = warnings_of(text);
  ASSERT_EQ(warnings.size(), 1u) << (warnings.empty() ? "" : warnings[0].to_string());
  const int line = line_of(text, at_line);
  EXPECT_TRUE(warnings[0].warning);
  EXPECT_EQ(warnings[0].to_string(), "w.eds:" + std::to_string(line) + ": warning: " + reason);
}

ObjectDictionary load_fixture(const std::string& name, EdsFileInfo* info = nullptr) {
  EdsError error;
  std::vector<EdsError> warnings;
  auto od = canopen::load_eds(kDataDir + name, error, info, &warnings);
  EXPECT_TRUE(od.has_value()) << error.to_string();
  for (const auto& w : warnings) ADD_FAILURE() << w.to_string();
  return od ? std::move(*od) : ObjectDictionary{};
}

Bytes u32(std::uint32_t v) { return ObjectDictionary::encode(DataType::Unsigned32, v); }

// Every EDS-visible property of every entry is equal (data type entries from [DummyUsage]
// excluded: a dictionary built in code has none, its EDS declares them).
void expect_same_dictionary(const ObjectDictionary& a, const ObjectDictionary& b) {
  auto visible = [](const ObjectDictionary& od) {
    std::vector<const canopen::OdObject*> v;
    for (const auto& [i, o] : od.objects())
      if (!(o.code == ObjectCode::DefType && i <= 7)) v.push_back(&o);
    return v;
  };
  const auto va = visible(a), vb = visible(b);
  ASSERT_EQ(va.size(), vb.size());
  for (std::size_t i = 0; i < va.size(); ++i) {
    const auto& oa = *va[i];
    const auto& ob = *vb[i];
    SCOPED_TRACE(::testing::Message() << "object 0x" << std::hex << oa.index);
    EXPECT_EQ(oa.index, ob.index);
    EXPECT_EQ(oa.name, ob.name);
    EXPECT_EQ(oa.code, ob.code);
    EXPECT_EQ(oa.obj_flags, ob.obj_flags);
    ASSERT_EQ(oa.entries.size(), ob.entries.size());
    for (auto ia = oa.entries.begin(), ib = ob.entries.begin(); ia != oa.entries.end(); ++ia, ++ib) {
      const auto& ea = ia->second;
      const auto& eb = ib->second;
      SCOPED_TRACE(::testing::Message() << "sub " << std::dec << int(ea.sub));
      EXPECT_EQ(ea.sub, eb.sub);
      EXPECT_EQ(ea.name, eb.name);
      EXPECT_EQ(ea.type, eb.type);
      EXPECT_EQ(ea.access, eb.access);
      EXPECT_EQ(ea.process_data, eb.process_data);
      EXPECT_EQ(ea.pdo_mappable, eb.pdo_mappable);
      EXPECT_EQ(ea.node_id_relative, eb.node_id_relative);
      EXPECT_EQ(ea.default_value, eb.default_value);
      EXPECT_EQ(ea.low_limit, eb.low_limit);
      EXPECT_EQ(ea.high_limit, eb.high_limit);
    }
  }
}

}  // namespace

// ---- reading a realistic file ----------------------------------------------------------------

TEST(EdsReader, MinimalFileIsClean) {
  EXPECT_TRUE(canopen::check_eds(kMinimal, "minimal.eds").empty());
}

TEST(EdsReader, IoModuleFileAndDeviceInfo) {
  EdsFileInfo info;
  load_fixture("io_module.eds", &info);
  EXPECT_EQ(info.file_name, "io_module.eds");
  EXPECT_EQ(info.file_version, 1);
  EXPECT_EQ(info.file_revision, 3);
  EXPECT_EQ(info.eds_version, "4.0");
  EXPECT_EQ(info.description, "vplant test I/O module (CiA 401 style)");
  EXPECT_EQ(info.creation_time, "09:30AM");
  EXPECT_EQ(info.creation_date, "03-14-2026");
  EXPECT_EQ(info.created_by, "vplant tests");
  EXPECT_EQ(info.modification_time, "04:45PM");
  EXPECT_EQ(info.modification_date, "03-15-2026");
  EXPECT_EQ(info.modified_by, "vplant tests");
  EXPECT_EQ(info.vendor_name, "vplant test vendor");
  EXPECT_EQ(info.vendor_number, 0xABCu);
  EXPECT_EQ(info.product_name, "IO-16 test module");
  EXPECT_EQ(info.product_number, 0x4010u);
  EXPECT_EQ(info.revision_number, 0x10002u);
  EXPECT_EQ(info.order_code, "IO16-T");
  EXPECT_EQ(info.baud_rates_kbit, (std::vector<unsigned>{125, 250, 500, 1000}));
  EXPECT_FALSE(info.simple_boot_up_master);
  EXPECT_TRUE(info.simple_boot_up_slave);
  EXPECT_EQ(info.granularity, 8);
  EXPECT_EQ(info.nr_of_rx_pdo, 2);
  EXPECT_EQ(info.nr_of_tx_pdo, 2);
  EXPECT_FALSE(info.lss_supported);
  EXPECT_EQ(info.dummy_usage, 0xFC);
  ASSERT_EQ(info.comments.size(), 2u);
  EXPECT_EQ(info.comments[1], "Outputs arrive by RPDO1 (digital) and RPDO2 (analogue).");
}

TEST(EdsReader, IoModuleTypesAccessDefaultsAndLimits) {
  const auto od = load_fixture("io_module.eds");
  const auto* e = od.entry(0x1000, 0);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->type, DataType::Unsigned32);
  EXPECT_EQ(e->access, Access::ReadOnly);
  EXPECT_EQ(e->default_value, u32(0x000F0191));
  EXPECT_EQ(od.object(0x1000)->code, ObjectCode::Var);

  // "[100a]", ObjectType=7, DataType=9, AccessType=CONST: hex index in lower case, decimal codes.
  e = od.entry(0x100A, 0);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->type, DataType::VisibleString);
  EXPECT_EQ(e->access, Access::Const);
  EXPECT_EQ(std::string(e->default_value.begin(), e->default_value.end()), "SW 3.4.5-rc1");

  EXPECT_EQ(od.entry(0x1015, 0)->default_value, (Bytes{0, 0}));  // "DefaultValue=" = 0
  e = od.entry(0x2000, 0);  // octal 010
  EXPECT_EQ(e->default_value, Bytes{8});
  EXPECT_EQ(e->low_limit, Bytes{1});
  EXPECT_EQ(e->high_limit, Bytes{200});
  e = od.entry(0x2001, 0);
  EXPECT_EQ(e->type, DataType::Integer32);
  EXPECT_EQ(e->as<std::int32_t>(), -1000);
  EXPECT_TRUE(e->pdo_mappable);
  EXPECT_EQ(canopen::decode_signed(*e->low_limit), -50000);
  EXPECT_EQ(od.entry(0x2003, 0)->access, Access::WriteOnly);
  e = od.entry(0x2004, 0);
  EXPECT_EQ(e->type, DataType::Real32);
  EXPECT_FLOAT_EQ(e->as<float>(), 1.5f);
  EXPECT_FLOAT_EQ(canopen::value_as<float>(DataType::Real32, *e->low_limit), -100.0f);
  EXPECT_EQ(od.entry(0x2005, 0)->default_value, (Bytes{0xDE, 0xAD, 0xBE, 0xEF, 0x01}));
  EXPECT_EQ(od.object(0x2006)->code, ObjectCode::Domain);
  EXPECT_EQ(od.entry(0x2006, 0)->type, DataType::Domain);
  EXPECT_EQ(od.entry(0x2006, 0)->access, Access::ReadWrite);
  EXPECT_TRUE(od.entry(0x2006, 0)->default_value.empty());
  EXPECT_EQ(od.entry(0x2007, 0)->as<std::uint64_t>(), 0x0000000100000002ull);
  EXPECT_EQ(od.entry(0x2008, 0)->default_value, (Bytes{0x00, 0x00, 0x80}));  // INTEGER24 minimum
  EXPECT_EQ(od.object(0x2100)->code, ObjectCode::Record);
  EXPECT_DOUBLE_EQ(od.entry(0x2100, 2)->as<double>(), -0.25);
  EXPECT_EQ(od.entry(0x2100, 2)->type, DataType::Real64);
  EXPECT_EQ(od.get_string(0x2100, 3), "mbar");

  // rwr / rww: read-write with the process direction kept.
  EXPECT_EQ(od.entry(0x6401, 1)->access, Access::ReadWrite);
  EXPECT_EQ(od.entry(0x6401, 1)->process_data, ProcessData::Input);
  EXPECT_EQ(od.entry(0x6401, 2)->default_value, (Bytes{0xFF, 0xFF}));
  EXPECT_EQ(od.entry(0x6411, 1)->process_data, ProcessData::Output);
  EXPECT_EQ(canopen::decode_signed(*od.entry(0x6411, 1)->low_limit), -10000);
  EXPECT_EQ(*od.entry(0x6411, 2)->high_limit, (Bytes{0xFF, 0x7F}));  // HighLimit=0x7FFF on an INTEGER16
  EXPECT_EQ(od.entry(0x6423, 0)->type, DataType::Boolean);
  EXPECT_EQ(od.entry(0x1001, 0)->pdo_mappable, true);
}

TEST(EdsReader, NodeRelativeDefaultsInEverySpelling) {
  const auto od = load_fixture("io_module.eds");
  const std::pair<std::uint16_t, std::uint32_t> cases[] = {
      {0x1014, 0x80},    // $NODEID+0x80
      {0x1400, 0x200},   // $NODEID + 0x200
      {0x1401, 0x300},   // 0x300+$NODEID
      {0x1801, 0x280},   // $nodeid+0x280
  };
  for (const auto& [index, base] : cases) {
    const auto* e = od.entry(index, index == 0x1014 ? 0 : 1);
    ASSERT_TRUE(e);
    EXPECT_TRUE(e->node_id_relative) << std::hex << index;
    EXPECT_EQ(e->default_value, u32(base));
    EXPECT_EQ(e->default_for_node(5), u32(base + 5));
  }
  EXPECT_EQ(od.entry(0x1200, 1)->default_for_node(127), u32(0x67F));
}

TEST(EdsReader, CompactArraysWithNameAndValueSections) {
  const auto od = load_fixture("io_module.eds");
  const auto* obj = od.object(0x1016);
  ASSERT_TRUE(obj);
  EXPECT_EQ(obj->code, ObjectCode::Array);
  ASSERT_EQ(obj->entries.size(), 3u);
  EXPECT_EQ(obj->entries.at(0).name, "NrOfObjects");
  EXPECT_EQ(obj->entries.at(0).access, Access::ReadOnly);
  EXPECT_EQ(obj->entries.at(0).default_value, Bytes{2});
  EXPECT_EQ(obj->entries.at(1).name, "Consumer heartbeat time1");
  EXPECT_EQ(obj->entries.at(2).name, "Consumer heartbeat time2");
  EXPECT_EQ(obj->entries.at(2).type, DataType::Unsigned32);
  EXPECT_EQ(obj->entries.at(2).access, Access::ReadWrite);

  EXPECT_EQ(od.entry(0x6000, 1)->name, "Digital inputs 1-8");  // [6000Name]
  EXPECT_EQ(od.entry(0x6000, 2)->name, "Digital inputs 9-16");
  EXPECT_TRUE(od.entry(0x6000, 2)->pdo_mappable);
  EXPECT_EQ(od.entry(0x6200, 1)->default_value, Bytes{0});
  EXPECT_EQ(od.entry(0x6200, 2)->default_value, Bytes{0x5A});  // [6200Value]
  EXPECT_EQ(od.entry(0x6200, 2)->process_data, ProcessData::Output);
  EXPECT_EQ(od.entry(0x6426, 2)->default_value, u32(0x10));
}

TEST(EdsReader, DummyUsageDeclaresDataTypeEntries) {
  const auto od = load_fixture("io_module.eds");
  EXPECT_FALSE(od.object(0x0001));  // Dummy0001=0
  for (std::uint16_t t = 2; t <= 7; ++t) {
    const auto* o = od.object(t);
    ASSERT_TRUE(o) << t;
    EXPECT_EQ(o->code, ObjectCode::DefType);
    EXPECT_EQ(o->entries.at(0).access, Access::Const);
    EXPECT_EQ(o->entries.at(0).default_value, u32(static_cast<std::uint32_t>(canopen::type_size(DataType(t)) * 8)));
  }
}

TEST(EdsReader, CrLfCaseAndSpacingVariantsGiveTheSameDictionary) {
  const std::string lf = read_file(kDataDir + "io_module.eds");
  std::string variant;
  for (char c : lf) {
    if (c == '\n') variant += "\r\n";
    else variant += c;
  }
  variant = "\xEF\xBB\xBF" + variant;  // UTF-8 byte order mark
  auto replace_all = [&](const std::string& from, const std::string& to) {
    for (auto pos = variant.find(from); pos != std::string::npos; pos = variant.find(from, pos + to.size())) {
      variant.replace(pos, from.size(), to);
    }
  };
  replace_all("ParameterName=", "PARAMETERNAME = ");
  replace_all("[DeviceInfo]", "[deviceinfo]");
  replace_all("[2000]", "[0x2000]");
  replace_all("DefaultValue=", "  defaultvalue=\t");
  EdsError error;
  EdsFileInfo a, b;
  std::vector<EdsError> warnings;
  auto od_lf = canopen::parse_eds(lf, "lf.eds", error, &a);
  ASSERT_TRUE(od_lf) << error.to_string();
  auto od_variant = canopen::parse_eds(variant, "crlf.eds", error, &b, &warnings);
  ASSERT_TRUE(od_variant) << error.to_string();
  EXPECT_TRUE(warnings.empty());
  expect_same_dictionary(*od_lf, *od_variant);
  EXPECT_EQ(canopen::write_eds(*od_lf, a), canopen::write_eds(*od_variant, b));
}

TEST(EdsReader, CompactPdoAddsTheUndescribedPdoObjects) {
  EdsFileInfo info;
  const auto od = load_fixture("compact_pdo.eds", &info);
  EXPECT_EQ(info.compact_pdo, 0x13);
  EXPECT_TRUE(info.lss_supported);
  // RPDO1: communication (COB-ID, transmission type, event timer) and an empty mapping.
  ASSERT_TRUE(od.object(0x1400) && od.object(0x1600));
  EXPECT_EQ(od.entry(0x1400, 0)->default_value, Bytes{5});
  EXPECT_EQ(od.entry(0x1400, 0)->access, Access::Const);
  EXPECT_TRUE(od.entry(0x1400, 1)->node_id_relative);
  EXPECT_EQ(od.entry(0x1400, 1)->default_value, u32(0x200));
  EXPECT_TRUE(od.entry(0x1400, 2));
  EXPECT_FALSE(od.entry(0x1400, 3));  // bit 2 not set
  EXPECT_EQ(od.entry(0x1400, 5)->type, DataType::Unsigned16);
  EXPECT_EQ(od.object(0x1600)->entries.size(), 65u);
  EXPECT_EQ(od.entry(0x1600, 0)->access, Access::ReadWrite);
  // TPDO1: the described communication object stays as written; its mapping is added.
  EXPECT_EQ(od.entry(0x1800, 2)->default_value, Bytes{254});
  EXPECT_FALSE(od.entry(0x1800, 5));
  ASSERT_TRUE(od.object(0x1A00));
  // TPDO2: both objects implicit.
  EXPECT_EQ(od.entry(0x1801, 1)->default_value, u32(0x280));
  ASSERT_TRUE(od.object(0x1A01));
  EXPECT_FALSE(od.object(0x1802));
  EXPECT_FALSE(od.object(0x1401));
}

TEST(EdsReader, DcfParameterValueBecomesTheValueAfterReset) {
  const std::string text = with(kMinimal, "DefaultValue=7\n", "DefaultValue=7\nParameterValue=0x2A\n");
  EdsError error;
  auto od = canopen::parse_eds(text, "node.dcf", error);
  ASSERT_TRUE(od) << error.to_string();
  EXPECT_EQ(od->entry(0x2000, 0)->default_value, Bytes{42});
}

// ---- errors: one test per kind, file and line exact --------------------------------------------

TEST(EdsErrors, SyntaxLineThatIsNeitherSectionNorKey) {
  expect_error(with(kMinimal, "DefaultValue=7\n", "DefaultValue=7\nthis is not ini\n"), "this is not ini",
               "expected '[section]' or 'key=value'");
}

TEST(EdsErrors, SectionHeaderWithoutClosingBracket) {
  expect_error(with(kMinimal, "[2000]", "[2000"), "[2000", "missing ']' in section header");
}

TEST(EdsErrors, TextAfterSectionHeader) {
  expect_error(with(kMinimal, "[2000]", "[2000] trailing"), "[2000] trailing", "unexpected text after ']'");
}

TEST(EdsErrors, EmptySectionNameAndEmptyKey) {
  expect_error(with(kMinimal, "[2000]", "[]"), "[]", "empty section name");
  expect_error(with(kMinimal, "DefaultValue=7\n", "DefaultValue=7\n=5\n"), "=5", "empty key name");
}

TEST(EdsErrors, KeyOutsideOfAnySection) {
  expect_error("Stray=1\n" + kMinimal, "Stray=1", "key 'Stray' outside of any section");
}

TEST(EdsErrors, DuplicateSection) {
  const std::string text = kMinimal + "\n[FileInfo]\nFileName=again.eds\n";
  const int first = line_of(kMinimal, "[FileInfo]");
  EdsError error;
  ASSERT_FALSE(canopen::parse_eds(text, "bad.eds", error));
  EXPECT_EQ(error.to_string(), "bad.eds:" + std::to_string(line_of(text, "FileName=again.eds") - 1) +
                                 ": duplicate section [FileInfo] (first at line " + std::to_string(first) + ")");
}

TEST(EdsErrors, DuplicateKey) {
  const std::string text = with(kMinimal, "DefaultValue=7\nPDOMapping=0\n", "DefaultValue=7\nPDOMapping=0\nPDOMapping=1\n");
  const int first = line_of(text, "DefaultValue=7") + 1;
  expect_error(text, "PDOMapping=1", "duplicate key 'PDOMapping' in [2000] (first at line " + std::to_string(first) + ")");
}

TEST(EdsErrors, MissingParameterName) {
  expect_error(with(kMinimal, "ParameterName=Setpoint\n", ""), "[2000]", "missing ParameterName in [2000]");
}

TEST(EdsErrors, MissingDataType) {
  expect_error(with(kMinimal, "ParameterName=Setpoint\nObjectType=0x7\nDataType=0x0005\n", "ParameterName=Setpoint\nObjectType=0x7\n"),
               "[2000]", "missing DataType in [2000]");
}

TEST(EdsErrors, MissingAccessType) {
  expect_error(with(kMinimal, "AccessType=rw\n", ""), "[2000]", "missing AccessType in [2000]");
}

TEST(EdsErrors, UnknownDataType) {
  const auto text = with(kMinimal, "ParameterName=Setpoint\nObjectType=0x7\nDataType=0x0005\n",
                         "ParameterName=Setpoint\nObjectType=0x7\nDataType=0x0042\n");
  expect_error(text, "DataType=0x0042", "unknown DataType 0x0042");
}

TEST(EdsErrors, UnknownAccessType) {
  expect_error(with(kMinimal, "AccessType=rw\n", "AccessType=rx\n"), "AccessType=rx",
               "unknown AccessType 'rx' (ro, wo, rw, rwr, rww, const)");
}

TEST(EdsErrors, UnknownObjectType) {
  expect_error(with(kMinimal, "ParameterName=Setpoint\nObjectType=0x7\n", "ParameterName=Setpoint\nObjectType=0x3\n"),
               "ObjectType=0x3", "unknown ObjectType 0x03 (0x2 DOMAIN, 0x5 DEFTYPE, 0x6 DEFSTRUCT, 0x7 VAR, 0x8 ARRAY, 0x9 RECORD)");
}

TEST(EdsErrors, DefaultOutOfRangeForItsType) {
  expect_error(with(kMinimal, "DefaultValue=7\n", "DefaultValue=300\n"), "DefaultValue=300",
               "DefaultValue: 300 is out of range for UNSIGNED8 (0..255)");
  expect_error(with(kMinimal, "DefaultValue=7\n", "DefaultValue=-1\n"), "DefaultValue=-1",
               "DefaultValue: -1 is out of range for UNSIGNED8 (0..255)");
  auto i8 = with(kMinimal, "ParameterName=Setpoint\nObjectType=0x7\nDataType=0x0005\n",
                 "ParameterName=Setpoint\nObjectType=0x7\nDataType=0x0002\n");
  expect_error(with(i8, "DefaultValue=7\n", "DefaultValue=-129\n"), "DefaultValue=-129",
               "DefaultValue: -129 is out of range for INTEGER8 (-128..127)");
  expect_error(with(i8, "DefaultValue=7\n", "DefaultValue=0x1FF\n"), "DefaultValue=0x1FF",
               "DefaultValue: 0x1FF is out of range for INTEGER8 (-128..127)");
}

TEST(EdsErrors, ValueThatIsNotANumber) {
  expect_error(with(kMinimal, "DefaultValue=7\n", "DefaultValue=12abc\n"), "DefaultValue=12abc",
               "DefaultValue: '12abc' is not a number");
  expect_error(with(kMinimal, "DefaultValue=7\n", "DefaultValue=09\n"), "DefaultValue=09",
               "DefaultValue: '09' is not a number");  // leading 0 = octal
  expect_error(with(kMinimal, "DefaultValue=7\n", "DefaultValue=0x\n"), "DefaultValue=0x", "DefaultValue: '0x' is not a number");
}

TEST(EdsErrors, MalformedNodeIdExpression) {
  expect_error(with(kMinimal, "DefaultValue=7\n", "DefaultValue=$NODEID*2\n"), "DefaultValue=$NODEID*2",
               "DefaultValue: '$NODEID*2' is not of the form $NODEID+x");
  expect_error(with(kMinimal, "DefaultValue=7\n", "DefaultValue=$NODEID+\n"), "DefaultValue=$NODEID+",
               "DefaultValue: '$NODEID+' is not of the form $NODEID+x");
  auto real = with(kMinimal, "ParameterName=Setpoint\nObjectType=0x7\nDataType=0x0005\n",
                   "ParameterName=Setpoint\nObjectType=0x7\nDataType=0x0008\n");
  expect_error(with(real, "DefaultValue=7\n", "DefaultValue=$NODEID+1\n"), "DefaultValue=$NODEID+1",
               "DefaultValue: $NODEID needs an integer type, not REAL32");
  expect_error(with(kMinimal, "DefaultValue=7\n", "DefaultValue=7\nLowLimit=$NODEID\n"), "LowLimit=$NODEID",
               "LowLimit: $NODEID is only supported in DefaultValue and ParameterValue");
}

TEST(EdsErrors, RealAndByteStringSyntax) {
  auto real = with(kMinimal, "ParameterName=Setpoint\nObjectType=0x7\nDataType=0x0005\n",
                   "ParameterName=Setpoint\nObjectType=0x7\nDataType=0x0008\n");
  expect_error(with(real, "DefaultValue=7\n", "DefaultValue=1e39\n"), "DefaultValue=1e39",
               "DefaultValue: 1e39 is out of range for REAL32");
  auto octets = with(kMinimal, "ParameterName=Setpoint\nObjectType=0x7\nDataType=0x0005\n",
                     "ParameterName=Setpoint\nObjectType=0x7\nDataType=0x000A\n");
  expect_error(with(octets, "DefaultValue=7\n", "DefaultValue=ABC\n"), "DefaultValue=ABC",
               "DefaultValue: odd number of hex digits in 'ABC'");
}

TEST(EdsErrors, LimitsContradictEachOtherOrTheDefault) {
  expect_error(with(kMinimal, "DefaultValue=7\n", "DefaultValue=7\nLowLimit=10\nHighLimit=5\n"), "HighLimit=5",
               "HighLimit 5 is below LowLimit 10");
  expect_error(with(kMinimal, "DefaultValue=7\n", "DefaultValue=7\nHighLimit=5\n"), "DefaultValue=7",
               "DefaultValue 7 is above HighLimit 5");
  expect_error(with(kMinimal, "DefaultValue=7\n", "DefaultValue=7\nLowLimit=8\n"), "DefaultValue=7",
               "DefaultValue 7 is below LowLimit 8");
}

TEST(EdsErrors, PdoMappingNotABoolean) {
  expect_error(with(kMinimal, "DefaultValue=7\nPDOMapping=0\n", "DefaultValue=7\nPDOMapping=2\n"), "PDOMapping=2",
               "PDOMapping must be 0 or 1");
}

TEST(EdsErrors, SubNumberDisagreesWithTheSubIndexSections) {
  expect_error(with(kMinimal, "SubNumber=4\n", "SubNumber=5\n"), "SubNumber=5",
               "SubNumber=5 but [1018] has 4 sub-index sections");
}

TEST(EdsErrors, RecordWithoutSubNumberOrSubIndexZero) {
  expect_error(with(kMinimal, "ObjectType=0x9\nSubNumber=4\n", "ObjectType=0x9\n"), "[1018]", "missing SubNumber in [1018]");
  const auto text = with(with(kMinimal, "SubNumber=4\n", "SubNumber=3\n"),
                         "[1018sub0]\nParameterName=Highest sub-index supported\nObjectType=0x7\nDataType=0x0005\nAccessType=ro\n"
                         "DefaultValue=3\nPDOMapping=0\n\n",
                         "");
  expect_error(text, "[1018]", "missing [1018sub0] (highest sub-index supported)");
}

TEST(EdsErrors, SubIndexSectionWithoutItsObject) {
  expect_error(kMinimal + "\n[2001sub0]\nParameterName=orphan\n", "[2001sub0]", "[2001sub0] has no object section [2001]");
}

TEST(EdsErrors, SubIndexSectionForAVar) {
  expect_error(kMinimal + "\n[2000sub1]\nParameterName=stray\n", "[2000sub1]",
               "[2000sub1]: object [2000] is a VAR and has no sub-indices");
}

TEST(EdsErrors, SubIndexOutOfRangeAndSubWithWrongObjectType) {
  expect_error(kMinimal + "\n[1018subFF]\nParameterName=x\n", "[1018subFF]", "[1018subFF]: sub-index 255 is out of range (0..254)");
  expect_error(with(kMinimal, "ParameterName=Vendor-ID\nObjectType=0x7\n", "ParameterName=Vendor-ID\nObjectType=0x8\n"),
               "ObjectType=0x8", "a sub-index must have ObjectType 0x7 (VAR)");
}

TEST(EdsErrors, SubNumberOnAVar) {
  expect_error(with(kMinimal, "DefaultValue=7\n", "DefaultValue=7\nSubNumber=1\n"), "SubNumber=1",
               "SubNumber is not allowed for a VAR object");
}

TEST(EdsErrors, MandatoryObjectMissing) {
  auto text = with(kMinimal, "SupportedObjects=3\n1=0x1000\n2=0x1001\n3=0x1018\n", "SupportedObjects=2\n1=0x1000\n2=0x1018\n");
  text = with(text,
              "[1001]\nParameterName=Error register\nObjectType=0x7\nDataType=0x0005\nAccessType=ro\nDefaultValue=0\nPDOMapping=0\n\n",
              "");
  expect_error(text, "[MandatoryObjects]", "mandatory object 0x1001 missing (CiA 306: 0x1000, 0x1001, 0x1018)");
}

TEST(EdsErrors, MandatoryObjectsSectionMissing) {
  const auto text = with(kMinimal, "[MandatoryObjects]\nSupportedObjects=3\n1=0x1000\n2=0x1001\n3=0x1018\n", "");
  EdsError error;
  ASSERT_FALSE(canopen::parse_eds(text, "bad.eds", error));
  EXPECT_EQ(error.to_string(), "bad.eds:1: missing section [MandatoryObjects]");
}

TEST(EdsErrors, ListedObjectWithoutSection) {
  expect_error(with(kMinimal, "SupportedObjects=1\n1=0x2000\n", "SupportedObjects=2\n1=0x2000\n2=0x2001\n"), "2=0x2001",
               "0x2001 is listed in [ManufacturerObjects] but has no section [2001]");
}

TEST(EdsErrors, SectionNotListed) {
  expect_error(kMinimal + "\n[2001]\nParameterName=unlisted\nDataType=0x0005\nAccessType=rw\n", "[2001]",
               "[2001] is not listed in [MandatoryObjects], [OptionalObjects] or [ManufacturerObjects]");
}

TEST(EdsErrors, ObjectListedTwice) {
  const auto text = with(kMinimal, "SupportedObjects=1\n1=0x2000\n", "SupportedObjects=2\n1=0x2000\n2=0x2000\n");
  expect_error(text, "2=0x2000", "0x2000 is listed twice (first at line " + std::to_string(line_of(text, "1=0x2000")) + ")");
}

TEST(EdsErrors, ObjectListEntriesAndCount) {
  expect_error(with(kMinimal, "SupportedObjects=1\n1=0x2000\n", "SupportedObjects=2\n1=0x2000\n"), "SupportedObjects=2",
               "SupportedObjects=2 but [ManufacturerObjects] lists 1 entry");  // strict; a warning otherwise
  expect_error(with(kMinimal, "SupportedObjects=1\n1=0x2000\n", "SupportedObjects=2\n2=0x2000\n"), "SupportedObjects=2",
               "entry 1 missing in [ManufacturerObjects] (SupportedObjects=2)");  // a gap is always an error
  // Entries beyond the count: strict, the deviation; tolerant, a gap below them is still an error.
  const auto beyond = with(kMinimal, "SupportedObjects=1\n1=0x2000\n", "SupportedObjects=1\n1=0x2000\n3=0x2001\n");
  expect_error(beyond, "SupportedObjects=1",
               "SupportedObjects=1 but [ManufacturerObjects] lists entries up to 3");
  EdsError gap;
  EXPECT_FALSE(canopen::parse_eds(beyond, "bad.eds", gap));
  EXPECT_EQ(gap.reason, "entry 2 missing in [ManufacturerObjects] (entries up to 3)");
  expect_error(with(kMinimal, "SupportedObjects=1\n1=0x2000\n", "1=0x2000\n"), "[ManufacturerObjects]",
               "missing SupportedObjects in [ManufacturerObjects]");
  expect_error(with(kMinimal, "SupportedObjects=1\n1=0x2000\n", "SupportedObjects=1\n1=0x2000\nfirst=0x2000\n"), "first=0x2000",
               "unexpected key 'first' in [ManufacturerObjects]");
}

TEST(EdsErrors, SameObjectInTwoSpellings) {
  const auto text = kMinimal + "\n[0x2000]\nParameterName=again\n";
  expect_error(text, "[0x2000]", "[0x2000] describes the same entry as the section at line " + std::to_string(line_of(text, "[2000]")));
}

TEST(EdsErrors, IndexZeroIsNotAnObject) {
  expect_error(kMinimal + "\n[0000]\nParameterName=zero\n", "[0000]", "[0000]: index 0x0000 is not an object");
}

TEST(EdsErrors, CompactFormMisuse) {
  const std::string array = "[2001]\nParameterName=Array\nObjectType=0x8\nDataType=0x0005\nAccessType=rw\nDefaultValue=0\nCompactSubObj=2\n";
  EdsError ok;
  EXPECT_TRUE(canopen::parse_eds(minimal_with_2001(array), "ok.eds", ok)) << ok.to_string();
  expect_error(minimal_with_2001(with(array, "ObjectType=0x8", "ObjectType=0x9")), "CompactSubObj=2",
               "CompactSubObj is only allowed for ARRAY objects, and [2001] is a RECORD");  // strict
  expect_error(minimal_with_2001(with(array, "ObjectType=0x8", "ObjectType=0x7")), "CompactSubObj=2",
               "CompactSubObj is not allowed for a VAR object");
  expect_error(minimal_with_2001(array + "SubNumber=3\n"), "SubNumber=3", "both SubNumber and CompactSubObj given in [2001]");
  expect_error(minimal_with_2001(array + "\n[2001sub1]\nParameterName=x\n"), "[2001sub1]",
               "[2001sub1] conflicts with CompactSubObj in [2001]");
  expect_error(minimal_with_2001(array + "\n[2001Name]\nNrOfEntries=3\n1=first\n2=second\n"), "NrOfEntries=3",
               "NrOfEntries=3 but [2001Name] gives 2");
  expect_error(minimal_with_2001(array + "\n[2001Name]\nNrOfEntries=1\n1=first\n5=fifth\n"), "5=fifth",
               "'5' is not a sub-index of 0x2001 (1..2)");
  expect_error(minimal_with_2001(array + "\n[2001Value]\nNrOfEntries=1\n1=300\n"), "1=300",
               "value of sub-index 1: 300 is out of range for UNSIGNED8 (0..255)");
  expect_error(kMinimal + "\n[1018Name]\nNrOfEntries=0\n", "[1018Name]", "[1018Name] needs CompactSubObj in [1018]");
  expect_error(minimal_with_2001(with(array, "CompactSubObj=2", "CompactSubObj=255")), "CompactSubObj=255",
               "CompactSubObj: 255 is out of range (0..254)");
}

TEST(EdsErrors, FileThatCannotBeOpened) {
  EdsError error;
  EXPECT_FALSE(canopen::load_eds("/nonexistent/device.eds", error));
  EXPECT_EQ(error.to_string(), "/nonexistent/device.eds: cannot open: No such file or directory");
}

TEST(EdsErrors, TheFirstErrorByLineIsReported) {
  // Two problems; the one nearer the top wins, whatever the order in which they are found.
  auto text = with(kMinimal, "DefaultValue=7\n", "DefaultValue=300\n");
  text = with(text, "SupportedObjects=3\n", "SupportedObjects=4\n");
  expect_error(text, "SupportedObjects=4", "SupportedObjects=4 but [MandatoryObjects] lists 3 entries");
  const auto all = canopen::check_eds(text, "bad.eds");
  ASSERT_EQ(all.size(), 2u);
  EXPECT_LT(all[0].mark.line, all[1].mark.line);
}

// ---- warnings ------------------------------------------------------------------------------------

TEST(EdsWarnings, ConformanceDefectsThatKeepTheDictionary) {
  expect_warning(with(kMinimal, "DefaultValue=7\n", "DefaultValue=7\nColour=blue\n"), "Colour=blue",
                 "unknown key 'Colour' in [2000] ignored");
  expect_warning(kMinimal + "\n[Vendor Extras]\nx=1\n", "[Vendor Extras]", "unknown section [Vendor Extras] ignored");
  expect_warning(with(kMinimal, "NrOfRXPDO=0", "NrOfRXPDO=2"), "NrOfRXPDO=2", "NrOfRXPDO=2 but the file describes 0 RPDOs");
  expect_warning(with(kMinimal, "CreationDate=01-01-2026", "CreationDate=2026-01-01"), "CreationDate=2026-01-01",
                 "CreationDate '2026-01-01' is not mm-dd-yyyy");
  expect_warning(with(kMinimal, "CreatedBy=test\n", ""), "[FileInfo]", "missing CreatedBy in [FileInfo]");
  expect_warning(with(kMinimal, "VendorNumber=0x00000001", "VendorNumber=0x00000009"), "VendorNumber=0x00000009",
                 "VendorNumber 0x00000009 differs from 0x1018 sub 1 (0x00000001)");
  expect_warning(with(kMinimal, "[ManufacturerObjects]", "[OptionalObjects]"), "1=0x2000",
                 "0x2000 is a manufacturer-specific object: it belongs in [ManufacturerObjects]");
}

TEST(EdsWarnings, DefaultPdoMappingThatTheStackCannotUse) {
  const std::string tpdo_map = R"(
[OptionalObjects]
SupportedObjects=1
1=0x1A00

[1A00]
ParameterName=TPDO1 mapping parameter
ObjectType=0x9
SubNumber=2

[1A00sub0]
ParameterName=Number of mapped objects
DataType=0x0005
AccessType=rw
DefaultValue=1

[1A00sub1]
ParameterName=Mapped object 1
DataType=0x0007
AccessType=rw
DefaultValue=0x20000008
)";
  expect_warning(kMinimal + tpdo_map, "DefaultValue=0x20000008",
                 "default mapping 0x20000008: 0x2000 sub 0 is not PDO-mappable");
  expect_warning(with(kMinimal, "DefaultValue=7\nPDOMapping=0", "DefaultValue=7\nPDOMapping=1") +
                     with(tpdo_map, "DefaultValue=0x20000008", "DefaultValue=0x20000010"),
                 "DefaultValue=0x20000010", "default mapping 0x20000010: 0x2000 sub 0 is 8 bits long");
}

TEST(EdsWarnings, CheckListsErrorsAndWarningsInLineOrder) {
  auto text = with(kMinimal, "DefaultValue=7\n", "DefaultValue=300\n");
  text = with(text, "DefaultValue=0x00000191\n", "DefaultValue=0x00000191\nColour=blue\n");
  text = with(text, "CreatedBy=test\n", "");
  const auto all = canopen::check_eds(text, "x.eds");
  ASSERT_EQ(all.size(), 3u);
  EXPECT_EQ(all[0].to_string(), "x.eds:1: warning: missing CreatedBy in [FileInfo]");
  EXPECT_EQ(all[1].to_string(), "x.eds:" + std::to_string(line_of(text, "Colour=blue")) +
                                  ": warning: unknown key 'Colour' in [1000] ignored");
  EXPECT_EQ(all[2].to_string(), "x.eds:" + std::to_string(line_of(text, "DefaultValue=300")) +
                                  ": DefaultValue: 300 is out of range for UNSIGNED8 (0..255)");
}

// ---- writing -------------------------------------------------------------------------------------

TEST(EdsWriter, FixtureRoundTripsEntryByEntryAndByteByByte) {
  EdsFileInfo info;
  const auto od = load_fixture("io_module.eds", &info);
  const std::string text = canopen::write_eds(od, info);
  EXPECT_TRUE(canopen::check_eds(text, "written.eds").empty());
  EdsError error;
  EdsFileInfo info2;
  auto again = canopen::parse_eds(text, "written.eds", error, &info2);
  ASSERT_TRUE(again) << error.to_string();
  expect_same_dictionary(od, *again);
  EXPECT_EQ(canopen::write_eds(*again, info2), text);
}

TEST(EdsWriter, DictionaryBuiltInCodeRoundTripsWithoutWarnings) {
  auto od = vtest::make_generic_od();
  od.entry(0x6000, 0)->process_data = ProcessData::Output;
  od.entry(0x6001, 0)->process_data = ProcessData::Input;
  od.object(0x2001)->obj_flags = 0x1;
  EdsFileInfo info;
  info.file_name = "generic.eds";
  info.vendor_name = "vplant";
  info.product_name = "generic node";
  info.comments = {"built in code", "second line"};
  const std::string text = canopen::write_eds(od, info);
  const auto diagnostics = canopen::check_eds(text, "generic.eds");
  for (const auto& d : diagnostics) ADD_FAILURE() << d.to_string();
  EdsError error;
  EdsFileInfo info2;
  auto parsed = canopen::parse_eds(text, "generic.eds", error, &info2);
  ASSERT_TRUE(parsed) << error.to_string();
  expect_same_dictionary(od, *parsed);
  EXPECT_EQ(info2.comments, info.comments);
  EXPECT_EQ(info2.vendor_number, 0x12345678u);  // from 0x1018 sub 1
  EXPECT_EQ(canopen::write_eds(*parsed, info2), text);
}

TEST(EdsWriter, IsDeterministicAndWritesWhatCiA306Asks) {
  const auto od = vtest::make_generic_od();
  EdsFileInfo info;
  info.file_name = "generic.eds";
  info.creation_date = "02-03-2026";
  const std::string text = canopen::write_eds(od, info);
  EXPECT_EQ(canopen::write_eds(od, info), text);
  for (const char* expected : {
           "[FileInfo]\nFileName=generic.eds\nFileVersion=1\nFileRevision=0\nEDSVersion=4.0\n",
           "CreationTime=12:00AM\nCreationDate=02-03-2026\nCreatedBy=vplant\n",
           "SimpleBootUpMaster=0\nSimpleBootUpSlave=1\nGranularity=8\nDynamicChannelsSupported=0\nCompactPDO=0\n"
           "GroupMessaging=0\nNrOfRXPDO=2\nNrOfTXPDO=2\nLSS_Supported=0\n",
           "[DummyUsage]\nDummy0001=0\nDummy0002=1\n",
           "[MandatoryObjects]\nSupportedObjects=3\n1=0x1000\n2=0x1001\n3=0x1018\n",
           "[1800sub1]\nParameterName=COB-ID used by PDO\nObjectType=0x7\nDataType=0x0007\nAccessType=rw\n"
           "DefaultValue=$NODEID+0x180\nPDOMapping=0\n",
           "[2001]\nParameterName=I16 rw limited\nObjectType=0x7\nDataType=0x0003\nAccessType=rw\nDefaultValue=-5\n"
           "PDOMapping=0\nLowLimit=-100\nHighLimit=100\n",
           "[1018]\nParameterName=Identity object\nObjectType=0x9\nSubNumber=5\n",
           "[ManufacturerObjects]\nSupportedObjects=7\n1=0x2000\n",
       }) {
    EXPECT_NE(text.find(expected), std::string::npos) << expected;
  }
}

TEST(EdsWriter, ValuesKeepTheirBits) {
  ObjectDictionary od;
  od.add_var(0x1000, "Device type", DataType::Unsigned32, Access::ReadOnly, 0u);
  od.add_var(0x1001, "Error register", DataType::Unsigned8, Access::ReadOnly, 0);
  od.add_object(0x1018, "Identity object", ObjectCode::Record);
  od.add_entry(0x1018, 0, "Highest sub-index supported", DataType::Unsigned8, Access::ReadOnly, 1);
  od.add_entry(0x1018, 1, "Vendor-ID", DataType::Unsigned32, Access::ReadOnly, 0u);
  od.add_var(0x2000, "r32", DataType::Real32, Access::ReadWrite, 0.1f);
  od.add_var(0x2001, "r64", DataType::Real64, Access::ReadWrite, -1.0 / 3.0);
  od.add_var(0x2002, "i64", DataType::Integer64, Access::ReadWrite, std::numeric_limits<std::int64_t>::min());
  od.add_var(0x2003, "u64", DataType::Unsigned64, Access::ReadWrite, std::numeric_limits<std::uint64_t>::max());
  od.add_var(0x2004, "unicode", DataType::UnicodeString, Access::ReadWrite, Bytes{'G', 0, 0xFC, 0, 0xAC, 0x20, 0x3D, 0xD8, 0x00, 0xDE});
  od.add_var(0x2005, "octets", DataType::OctetString, Access::ReadWrite, Bytes{0x00, 0x7F, 0xFF});
  od.add_var(0x2006, "domain", DataType::Domain, Access::ReadWrite, Bytes{1, 2, 3});
  od.add_var(0x2007, "i56", DataType::Integer56, Access::ReadWrite, Bytes{0xFE, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF});
  od.add_var(0x2008, "time", DataType::TimeOfDay, Access::ReadWrite, Bytes{1, 2, 3, 4, 5, 6});
  auto& limited = od.add_var(0x2009, "limited r32", DataType::Real32, Access::ReadWrite, 1e-8f);
  limited.low_limit = ObjectDictionary::encode(DataType::Real32, -0.25f);
  limited.high_limit = ObjectDictionary::encode(DataType::Real32, 1e-7f);
  od.add_var(0x200A, "text", DataType::VisibleString, Access::ReadWrite, ObjectDictionary::encode(DataType::VisibleString, "a;b=c [d]"));
  EdsFileInfo info;
  info.dummy_usage = 0;
  const auto text = canopen::write_eds(od, info);
  EdsError error;
  std::vector<EdsError> warnings;
  auto parsed = canopen::parse_eds(text, "values.eds", error, nullptr, &warnings);
  ASSERT_TRUE(parsed) << error.to_string();
  for (const auto& w : warnings) ADD_FAILURE() << w.to_string();
  expect_same_dictionary(od, *parsed);
}

// ---- robustness ------------------------------------------------------------------------------------

TEST(EdsRobustness, MutatedFilesNeverCrashAndAlwaysExplainThemselves) {
  // Mostly a small file with every construct (fast under the sanitizers), every tenth time the
  // full fixture.
  const std::string fixture = read_file(kDataDir + "io_module.eds");
  ASSERT_FALSE(fixture.empty());
  const std::string small = with(kMinimal, "SupportedObjects=1\n1=0x2000\n", "SupportedObjects=3\n1=0x2000\n2=0x2001\n3=0x2002\n") +
                            R"(
[2001]
ParameterName=Array
ObjectType=0x8
DataType=0x0003
AccessType=rww
DefaultValue=-2
PDOMapping=1
LowLimit=-10
HighLimit=0x7FFF
CompactSubObj=3

[2001Name]
NrOfEntries=1
2=second

[2002]
ParameterName=Record
ObjectType=0x9
SubNumber=3

[2002sub0]
ParameterName=Highest sub-index supported
DataType=0x0005
AccessType=ro
DefaultValue=2

[2002sub1]
ParameterName=COB-ID
DataType=0x0007
AccessType=rw
DefaultValue=$NODEID+0x180

[2002sub2]
ParameterName=Text
DataType=0x0009
AccessType=rw
DefaultValue=some text
)";
  ASSERT_TRUE(canopen::check_eds(small, "small.eds").empty());
  std::mt19937 rng(306);
  auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
  const std::string garbage = "[]=;$0xNODEID+-\r\n\t\x00\xff sub 1018 DefaultValue CompactSubObj=";
  int rejected = 0;
  for (int i = 0; i < 300; ++i) {
    std::string t = i % 10 == 0 ? fixture : small;
    switch (i % 5) {
      case 0: t.resize(pick(t.size())); break;  // truncated anywhere
      case 1:
        for (int k = 0; k < 8; ++k) t[pick(t.size())] = static_cast<char>(pick(256));  // bytes flipped
        break;
      case 2:
        for (int k = 0; k < 4; ++k) t.insert(pick(t.size()), garbage.substr(pick(garbage.size())));
        break;
      case 3: {  // a line deleted or duplicated
        const auto a = t.rfind('\n', pick(t.size()));
        const auto b = t.find('\n', a == std::string::npos ? 0 : a + 1);
        if (a != std::string::npos && b != std::string::npos) {
          const std::string line = t.substr(a, b - a);
          if (pick(2)) t.erase(a, b - a);
          else t.insert(b, line);
        }
        break;
      }
      case 4:
        for (int k = 0; k < 3; ++k) {  // digits replaced by huge or odd numbers
          const auto at = t.find_first_of("0123456789", pick(t.size()));
          if (at != std::string::npos) t.replace(at, 1, pick(2) ? "99999999999999999999999" : "-0x");
        }
        break;
    }
    EdsError error;
    std::vector<EdsError> warnings;
    auto od = canopen::parse_eds(t, "fuzz.eds", error, nullptr, &warnings);
    const int lines = static_cast<int>(std::count(t.begin(), t.end(), '\n')) + 1;
    if (!od) {
      ++rejected;
      EXPECT_GE(error.mark.line, 1);
      EXPECT_LE(error.mark.line, lines);
      EXPECT_FALSE(error.reason.empty());
    } else {
      (void)canopen::write_eds(*od, EdsFileInfo{});
    }
    for (const auto& w : warnings) EXPECT_LE(w.mark.line, lines);
  }
  EXPECT_GT(rejected, 200) << rejected;  // the mutations do break files, and each says where
}

// ---- deviations that writing tools produce and masters tolerate ------------------------------------

namespace {

struct Quirk {
  const char* file;
  const char* line;    ///< the text of the line the finding is reported at
  const char* reason;  ///< the strict error; the tolerant warning is "reason: reading"
  const char* reading;
};

const Quirk kQuirks[] = {
    {"quirk_compact_record.dcf", "CompactSubObj=8", "CompactSubObj is only allowed for ARRAY objects, and [1600] is a RECORD",
     "read as 8 sub-indices of the record's DataType, like an ARRAY; sub 0 (number of mapped objects) counts the leading "
     "non-zero entries"},
    {"quirk_supported_objects.eds", "SupportedObjects=4", "SupportedObjects=4 but [OptionalObjects] lists 3 entries",
     "the 3 entries listed are read"},
    {"quirk_subnumber.eds", "SubNumber=4", "SubNumber=4 but [1400] has 3 sub-index sections", "the 3 sections given are read"},
    {"quirk_no_1000.eds", "[MandatoryObjects]", "mandatory object 0x1000 missing (CiA 306: 0x1000, 0x1001, 0x1018)",
     "0x1000 is UNSIGNED32, ro, 0x00000000 (no device profile)"},
    {"quirk_record_no_sub0.eds", "[1018]", "missing [1018sub0] (highest sub-index supported)",
     "sub 0 is UNSIGNED8, ro, 1 (the highest sub-index given)"},
    {"quirk_wo_low_limit.eds", "[2000]", "no DefaultValue, and 0 is below LowLimit 1", "the entry starts at LowLimit 1"},
    {"quirk_c_suffix.eds", "DefaultValue=0x1234567890ABCDEFLL",
     "C integer suffix 'LL' in '0x1234567890ABCDEFLL'", "read as 0x1234567890ABCDEF"},
    {"quirk_unlisted_object.eds", "[2001]",
     "[2001] is not listed in [MandatoryObjects], [OptionalObjects] or [ManufacturerObjects]",
     "read as if listed in [ManufacturerObjects]"},
    {"quirk_no_1001.eds", "[MandatoryObjects]", "mandatory object 0x1001 missing (CiA 306: 0x1000, 0x1001, 0x1018)",
     "0x1001 is UNSIGNED8, ro, 0 (the error register the node's EMCY service keeps)"},
    {"quirk_list_beyond_count.eds", "SupportedObjects=2", "SupportedObjects=2 but [OptionalObjects] lists entries up to 3",
     "the entries listed are read, as if SupportedObjects=3"},
};

}  // namespace

TEST(EdsQuirks, TheBaseFixtureIsClean) {
  EXPECT_TRUE(canopen::check_eds_file(kDataDir + "quirk_none.eds").empty());
  load_fixture("quirk_none.eds");
}

TEST(EdsQuirks, EachLoadsWithOneWarningAndStrictRejectsIt) {
  for (const auto& q : kQuirks) {
    SCOPED_TRACE(q.file);
    const std::string path = kDataDir + q.file;
    const int line = line_of(read_file(path), q.line);
    const std::string at = path + ":" + std::to_string(line) + ": ";
    EdsError error;
    std::vector<EdsError> warnings;
    const auto od = canopen::load_eds(path, error, nullptr, &warnings);
    ASSERT_TRUE(od.has_value()) << error.to_string();
    ASSERT_EQ(warnings.size(), 1u) << (warnings.empty() ? "" : warnings[0].to_string());
    EXPECT_EQ(warnings[0].to_string(), at + "warning: " + q.reason + ": " + q.reading);

    EXPECT_FALSE(canopen::load_eds(path, error, nullptr, nullptr, canopen::EdsStrictness::Strict));
    EXPECT_EQ(error.to_string(), at + q.reason);
    const auto checked = canopen::check_eds_file(path);  // `vplant eds --check` is strict
    ASSERT_EQ(checked.size(), 1u);
    EXPECT_EQ(checked[0].to_string(), at + q.reason);
  }
}

TEST(EdsQuirks, TheInterpretationsAreTheDocumentedOnes) {
  EdsError error;
  const auto compact = canopen::load_eds(kDataDir + "quirk_compact_record.dcf", error);
  ASSERT_TRUE(compact) << error.to_string();
  EXPECT_EQ(compact->object(0x1600)->code, ObjectCode::Record);
  EXPECT_EQ(compact->get<std::uint8_t>(0x1600, 0), 1);  // one object mapped (from [1600Value])
  EXPECT_EQ(compact->entry(0x1600, 0)->access, Access::ReadWrite);  // masters write it
  EXPECT_EQ(compact->get<std::uint32_t>(0x1600, 1), 0x20000010u);
  EXPECT_EQ(compact->get<std::uint32_t>(0x1600, 2), 0u);
  ASSERT_NE(compact->entry(0x1600, 8), nullptr);  // CompactSubObj=8 sub-indices
  EXPECT_EQ(compact->entry(0x1600, 8)->type, DataType::Unsigned32);

  const auto no_1000 = canopen::load_eds(kDataDir + "quirk_no_1000.eds", error);
  ASSERT_TRUE(no_1000) << error.to_string();
  ASSERT_NE(no_1000->entry(0x1000, 0), nullptr);
  EXPECT_EQ(no_1000->entry(0x1000, 0)->access, Access::ReadOnly);
  EXPECT_EQ(no_1000->get<std::uint32_t>(0x1000, 0), 0u);

  const auto no_sub0 = canopen::load_eds(kDataDir + "quirk_record_no_sub0.eds", error);
  ASSERT_TRUE(no_sub0) << error.to_string();
  EXPECT_EQ(no_sub0->get<std::uint8_t>(0x1018, 0), 1);
  EXPECT_EQ(no_sub0->entry(0x1018, 0)->type, DataType::Unsigned8);

  const auto wo = canopen::load_eds(kDataDir + "quirk_wo_low_limit.eds", error);
  ASSERT_TRUE(wo) << error.to_string();
  EXPECT_EQ(wo->get<std::uint16_t>(0x2000, 0), 1);
  EXPECT_EQ(wo->entry(0x2000, 0)->default_value, ObjectDictionary::encode(DataType::Unsigned16, 1));

  const auto subnumber = canopen::load_eds(kDataDir + "quirk_subnumber.eds", error);
  ASSERT_TRUE(subnumber) << error.to_string();
  EXPECT_EQ(subnumber->object(0x1400)->entries.size(), 3u);

  const auto suffix = canopen::load_eds(kDataDir + "quirk_c_suffix.eds", error);
  ASSERT_TRUE(suffix) << error.to_string();
  EXPECT_EQ(suffix->get<std::uint64_t>(0x2001, 0), 0x1234567890ABCDEFull);

  const auto unlisted = canopen::load_eds(kDataDir + "quirk_unlisted_object.eds", error);
  ASSERT_TRUE(unlisted) << error.to_string();
  EXPECT_EQ(unlisted->get<std::uint8_t>(0x2001, 0), 20);
  EXPECT_EQ(unlisted->entry(0x2001, 0)->access, Access::ReadWrite);

  const auto no_1001 = canopen::load_eds(kDataDir + "quirk_no_1001.eds", error);
  ASSERT_TRUE(no_1001) << error.to_string();
  ASSERT_NE(no_1001->entry(0x1001, 0), nullptr);
  EXPECT_EQ(no_1001->entry(0x1001, 0)->type, DataType::Unsigned8);
  EXPECT_EQ(no_1001->entry(0x1001, 0)->access, Access::ReadOnly);
  EXPECT_EQ(no_1001->get<std::uint8_t>(0x1001, 0), 0);

  const auto beyond = canopen::load_eds(kDataDir + "quirk_list_beyond_count.eds", error);
  ASSERT_TRUE(beyond) << error.to_string();
  EXPECT_NE(beyond->object(0x1600), nullptr);  // the third entry, beyond SupportedObjects=2
  EXPECT_EQ(beyond->get<std::uint32_t>(0x1600, 1), 0x20000010u);
}

TEST(EdsQuirks, ACSuffixIsOnlyTakenOffAnInteger) {
  const std::string base = read_file(kDataDir + "quirk_none.eds");
  // Every C spelling is read with the one warning; text that is no suffix stays an error.
  for (const char* suffix : {"u", "UL", "lu", "ull", "LLU"}) {
    SCOPED_TRACE(suffix);
    EdsError error;
    std::vector<EdsError> warnings;
    const auto od = canopen::parse_eds(with(base, "HighLimit=100", std::string("HighLimit=100") + suffix), "s.eds", error,
                                       nullptr, &warnings);
    ASSERT_TRUE(od) << error.to_string();
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(od->entry(0x2000, 0)->high_limit, ObjectDictionary::encode(DataType::Unsigned16, 100));
  }
  for (const char* bad : {"HighLimit=100LLL", "HighLimit=100UU", "HighLimit=LL"}) {
    SCOPED_TRACE(bad);
    EdsError error;
    EXPECT_FALSE(canopen::parse_eds(with(base, "HighLimit=100", bad), "s.eds", error));
  }
}

TEST(EdsErrors, CobIdAbove7FFWithoutThe29BitFlagMatchesNoFrame) {
  for (const auto& [file, reason] :
       {std::pair{"cob_id_29_bit_without_flag.eds",
                  "0x1400 sub 1: COB-ID 0x1FFFFFFF has CAN-ID bits above 0x7FF without bit 29 (29-bit CAN-ID) set"},
        std::pair{"cob_id_node_id_overflow.eds", "0x1400 sub 1: COB-ID $NODEID+0xFFFFFFFF with node-ID 1 overflows 32 bits"}}) {
    SCOPED_TRACE(file);
    const std::string path = kDataDir + file;
    const std::string text = read_file(path);
    const int line = line_of(text, text.find("0x1FFFFFFF") != std::string::npos ? "DefaultValue=0x1FFFFFFF"
                                                                                : "DefaultValue=$NODEID+0xFFFFFFFF");
    EdsError error;
    EXPECT_FALSE(canopen::load_eds(path, error));
    EXPECT_EQ(error.to_string(), path + ":" + std::to_string(line) + ": " + reason);
  }
  // With bit 29 the same CAN-ID is a 29-bit one; a node-relative 11-bit CAN-ID must stay within
  // 0x7FF for every node-ID; a PDO marked not valid (bit 31) does not use its CAN-ID.
  const std::string base = read_file(kDataDir + "quirk_none.eds");
  EdsError error;
  EXPECT_TRUE(canopen::parse_eds(with(base, "DefaultValue=$NODEID+0x200", "DefaultValue=0x3FFFFFFF"), "ok.eds", error))
      << error.to_string();
  EXPECT_TRUE(canopen::parse_eds(with(base, "DefaultValue=$NODEID+0x200", "DefaultValue=0x9FFFFFFF"), "ok.eds", error))
      << error.to_string();
  expect_error(with(base, "DefaultValue=$NODEID+0x200", "DefaultValue=$NODEID+0x7F0"), "DefaultValue=$NODEID+0x7F0",
               "0x1400 sub 1: COB-ID $NODEID+0x000007F0 with node-ID 16 has CAN-ID bits above 0x7FF without bit 29 "
               "(29-bit CAN-ID) set");
}

TEST(EdsWarnings, AnOutOfRangePdoCountIsReportedOnceAsWritten) {
  const std::string base = read_file(kDataDir + "quirk_none.eds");
  expect_warning(with(base, "NrOfRXPDO=1", "NrOfRXPDO=65535"), "NrOfRXPDO=65535", "NrOfRXPDO: 65535 is out of range (0..512)");
}
