// SDO server, frame level: bytes in → bytes out on 0x600+N / 0x580+N (N = 5).
#include "devices/canopen/sdo_server.h"

#include <gtest/gtest.h>

#include "tests/devices/canopen/fake_node_links.h"
#include "tests/devices/canopen/generic_node.h"
#include "tests/support/canopen_harness.h"

using vtest::Frame;
using vtest::Frames;

namespace {

class SdoServerTest : public ::testing::Test {
 protected:
  explicit SdoServerTest(canopen::NodePolicy policy = {}) : h(vtest::make_generic_od(), policy, 5) {
    h.power_on();
    h.take();
  }
  Frames req(std::initializer_list<std::uint8_t> bytes) {
    h.send(Frame(0x605, bytes));
    return h.take();
  }
  vtest::CanopenHarness h;
};

Frame resp(std::initializer_list<std::uint8_t> bytes) { return Frame(0x585, bytes); }

}  // namespace

TEST_F(SdoServerTest, ExpeditedUploadUsesTheObjectSize) {
  EXPECT_EQ(req({0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0}), Frames{resp({0x43, 0x00, 0x10, 0x00, 0x91, 0x01, 0x00, 0x00})});
  EXPECT_EQ(req({0x40, 0x00, 0x20, 0x00, 0, 0, 0, 0}), Frames{resp({0x4F, 0x00, 0x20, 0x00, 0x07, 0, 0, 0})});
  EXPECT_EQ(req({0x40, 0x00, 0x60, 0x00, 0, 0, 0, 0}), Frames{resp({0x4B, 0x00, 0x60, 0x00, 0x34, 0x12, 0, 0})});
  EXPECT_EQ(req({0x40, 0x18, 0x10, 0x01, 0, 0, 0, 0}), Frames{resp({0x43, 0x18, 0x10, 0x01, 0x78, 0x56, 0x34, 0x12})});
}

TEST_F(SdoServerTest, SegmentedUploadWithToggle) {
  // "hello segmented world" = 21 bytes → 3 segments of 7.
  EXPECT_EQ(req({0x40, 0x02, 0x20, 0x00, 0, 0, 0, 0}), Frames{resp({0x41, 0x02, 0x20, 0x00, 21, 0, 0, 0})});
  EXPECT_EQ(req({0x60, 0, 0, 0, 0, 0, 0, 0}), Frames{resp({0x00, 'h', 'e', 'l', 'l', 'o', ' ', 's'})});
  EXPECT_EQ(req({0x70, 0, 0, 0, 0, 0, 0, 0}), Frames{resp({0x10, 'e', 'g', 'm', 'e', 'n', 't', 'e'})});
  EXPECT_EQ(req({0x60, 0, 0, 0, 0, 0, 0, 0}), Frames{resp({0x01, 'd', ' ', 'w', 'o', 'r', 'l', 'd'})});
}

TEST_F(SdoServerTest, SegmentedUploadWithPartialLastSegment) {
  // U64 = 8 bytes: one full segment and one with 1 byte (n = 6 unused → 0x0D / toggle 1: 0x1D).
  EXPECT_EQ(req({0x40, 0x06, 0x20, 0x00, 0, 0, 0, 0}), Frames{resp({0x41, 0x06, 0x20, 0x00, 8, 0, 0, 0})});
  EXPECT_EQ(req({0x60, 0, 0, 0, 0, 0, 0, 0}), Frames{resp({0x00, 0x88, 0x77, 0x66, 0x55, 0x44, 0x33, 0x22})});
  EXPECT_EQ(req({0x70, 0, 0, 0, 0, 0, 0, 0}), Frames{resp({0x1D, 0x11, 0, 0, 0, 0, 0, 0})});
}

TEST_F(SdoServerTest, WrongToggleAborts05030000) {
  req({0x40, 0x02, 0x20, 0x00, 0, 0, 0, 0});
  EXPECT_EQ(req({0x70, 0, 0, 0, 0, 0, 0, 0}), Frames{resp({0x80, 0x02, 0x20, 0x00, 0x00, 0x00, 0x03, 0x05})});
}

TEST_F(SdoServerTest, TimeoutAborts05040000) {
  req({0x40, 0x02, 0x20, 0x00, 0, 0, 0, 0});
  h.run_ms(999);
  EXPECT_TRUE(h.take().empty());
  h.run_ms(2);
  EXPECT_EQ(h.take(), Frames{resp({0x80, 0x02, 0x20, 0x00, 0x00, 0x00, 0x04, 0x05})});
}

TEST_F(SdoServerTest, UnknownCommandAborts05040001) {
  EXPECT_EQ(req({0xE0, 0x00, 0x10, 0x00, 0, 0, 0, 0}), Frames{resp({0x80, 0x00, 0x10, 0x00, 0x01, 0x00, 0x04, 0x05})});
  // Block download initiate is not supported either.
  EXPECT_EQ(req({0xC6, 0x00, 0x20, 0x00, 4, 0, 0, 0}), Frames{resp({0x80, 0x00, 0x20, 0x00, 0x01, 0x00, 0x04, 0x05})});
  // A segment without an open transfer: nothing names an object, so index and sub are 0.
  EXPECT_EQ(req({0x60, 0, 0, 0, 0, 0, 0, 0}), Frames{resp({0x80, 0x00, 0x00, 0x00, 0x01, 0x00, 0x04, 0x05})});
}

TEST_F(SdoServerTest, AccessAborts) {
  // 0x06010001 read of a write-only object, 0x06010002 write of a read-only / const object.
  EXPECT_EQ(req({0x40, 0x04, 0x20, 0x00, 0, 0, 0, 0}), Frames{resp({0x80, 0x04, 0x20, 0x00, 0x01, 0x00, 0x01, 0x06})});
  EXPECT_EQ(req({0x23, 0x03, 0x20, 0x00, 1, 2, 3, 4}), Frames{resp({0x80, 0x03, 0x20, 0x00, 0x02, 0x00, 0x01, 0x06})});
  EXPECT_EQ(req({0x23, 0x00, 0x10, 0x00, 1, 2, 3, 4}), Frames{resp({0x80, 0x00, 0x10, 0x00, 0x02, 0x00, 0x01, 0x06})});
  EXPECT_EQ(req({0x23, 0x05, 0x20, 0x00, 1, 2, 3, 4}), Frames{resp({0x80, 0x05, 0x20, 0x00, 0x02, 0x00, 0x01, 0x06})});
}

TEST_F(SdoServerTest, ExistenceAborts) {
  EXPECT_EQ(req({0x40, 0xFF, 0x2F, 0x00, 0, 0, 0, 0}), Frames{resp({0x80, 0xFF, 0x2F, 0x00, 0x00, 0x00, 0x02, 0x06})});
  EXPECT_EQ(req({0x40, 0x18, 0x10, 0x05, 0, 0, 0, 0}), Frames{resp({0x80, 0x18, 0x10, 0x05, 0x11, 0x00, 0x09, 0x06})});
}

TEST_F(SdoServerTest, ExpeditedDownloadAndSizeAborts) {
  EXPECT_EQ(req({0x2B, 0x00, 0x60, 0x00, 0xCD, 0xAB, 0, 0}), Frames{resp({0x60, 0x00, 0x60, 0x00, 0, 0, 0, 0})});
  EXPECT_EQ(h.node().od().get<std::uint16_t>(0x6000), 0xABCD);
  // 4 bytes to a U16: length too high; 1 byte to a U16: too low (strict by default).
  EXPECT_EQ(req({0x23, 0x00, 0x60, 0x00, 1, 2, 3, 4}), Frames{resp({0x80, 0x00, 0x60, 0x00, 0x12, 0x00, 0x07, 0x06})});
  EXPECT_EQ(req({0x2F, 0x00, 0x60, 0x00, 1, 0, 0, 0}), Frames{resp({0x80, 0x00, 0x60, 0x00, 0x13, 0x00, 0x07, 0x06})});
  // Size not indicated (0x22): the object's length is taken.
  EXPECT_EQ(req({0x22, 0x00, 0x60, 0x00, 0x11, 0x22, 0x33, 0x44}), Frames{resp({0x60, 0x00, 0x60, 0x00, 0, 0, 0, 0})});
  EXPECT_EQ(h.node().od().get<std::uint16_t>(0x6000), 0x2211);
}

TEST_F(SdoServerTest, ValueAborts) {
  // 0x06090031 / 0x06090032 from the entry's limits.
  EXPECT_EQ(req({0x2B, 0x01, 0x20, 0x00, 101, 0, 0, 0}), Frames{resp({0x80, 0x01, 0x20, 0x00, 0x31, 0x00, 0x09, 0x06})});
  EXPECT_EQ(req({0x2B, 0x01, 0x20, 0x00, 0x9B, 0xFF, 0, 0}), Frames{resp({0x80, 0x01, 0x20, 0x00, 0x32, 0x00, 0x09, 0x06})});
  // 0x06090030: a non-zero value written to 0x1003:00.
  EXPECT_EQ(req({0x2F, 0x03, 0x10, 0x00, 1, 0, 0, 0}), Frames{resp({0x80, 0x03, 0x10, 0x00, 0x30, 0x00, 0x09, 0x06})});
}

TEST_F(SdoServerTest, SegmentedDownload) {
  EXPECT_EQ(h.download(0x2002, 0, {'a', 'b', 'c', 'd', 'e', 'f', 'g', 'h', 'i'}), 0u);
  EXPECT_EQ(h.node().od().get_string(0x2002), "abcdefghi");
  // Toggle error in a download.
  req({0x21, 0x02, 0x20, 0x00, 9, 0, 0, 0});
  EXPECT_EQ(req({0x10, 1, 2, 3, 4, 5, 6, 7}), Frames{resp({0x80, 0x02, 0x20, 0x00, 0x00, 0x00, 0x03, 0x05})});
}

TEST_F(SdoServerTest, SegmentedDownloadSizeMismatchAborts06070010) {
  EXPECT_EQ(req({0x21, 0x02, 0x20, 0x00, 10, 0, 0, 0}), Frames{resp({0x60, 0x02, 0x20, 0x00, 0, 0, 0, 0})});
  EXPECT_EQ(req({0x00, 1, 2, 3, 4, 5, 6, 7}), Frames{resp({0x20, 0, 0, 0, 0, 0, 0, 0})});
  // Last segment brings the total to 8, not the indicated 10.
  EXPECT_EQ(req({0x1B, 8, 0, 0, 0, 0, 0, 0}), Frames{resp({0x80, 0x02, 0x20, 0x00, 0x10, 0x00, 0x07, 0x06})});
}

TEST_F(SdoServerTest, SegmentedDownloadOfANumericObject) {
  EXPECT_EQ(h.download(0x2006, 0, {1, 2, 3, 4, 5, 6, 7, 8}), 0u);
  EXPECT_EQ(h.node().od().get<std::uint64_t>(0x2006), 0x0807060504030201ull);
  EXPECT_EQ(h.download(0x2006, 0, {1, 2, 3, 4, 5, 6, 7, 8, 9}), 0x06070012u);
}

TEST_F(SdoServerTest, ShortRequestsAreIgnoredByDefault) {
  EXPECT_TRUE(req({0x40, 0x00, 0x10, 0x00}).empty());
}

TEST_F(SdoServerTest, ClientAbortCancelsSilently) {
  req({0x40, 0x02, 0x20, 0x00, 0, 0, 0, 0});
  EXPECT_TRUE(req({0x80, 0x02, 0x20, 0x00, 0, 0, 0, 0}).empty());
  // The transfer is gone: its next segment is answered like one without a transfer.
  EXPECT_EQ(req({0x60, 0, 0, 0, 0, 0, 0, 0}), Frames{resp({0x80, 0x00, 0x00, 0x00, 0x01, 0x00, 0x04, 0x05})});
}

TEST_F(SdoServerTest, NoAnswerInStoppedAnswersAgainInPreOperational) {
  h.nmt(0x02, 5);
  h.take();
  EXPECT_TRUE(req({0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0}).empty());
  h.nmt(0x80, 5);
  h.take();
  EXPECT_EQ(req({0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0}).size(), 1u);
}

namespace {
canopen::NodePolicy lenient() {
  canopen::NodePolicy p;
  p.sdo.size_mode = canopen::SdoPolicy::SizeMode::Lenient;
  p.sdo.pad_short_requests = true;
  return p;
}
class LenientSdoServerTest : public SdoServerTest {
 protected:
  LenientSdoServerTest() : SdoServerTest(lenient()) {}
};
}  // namespace

TEST_F(LenientSdoServerTest, ExtendsAndTruncates) {
  EXPECT_EQ(req({0x23, 0x00, 0x60, 0x00, 0x01, 0x02, 0x03, 0x04}).at(0).data[0], 0x60);
  EXPECT_EQ(h.node().od().get<std::uint16_t>(0x6000), 0x0201);
  EXPECT_EQ(req({0x2F, 0x01, 0x20, 0x00, 0xFB, 0, 0, 0}).at(0).data[0], 0x60);  // -5 as one byte
  EXPECT_EQ(h.node().od().get<int>(0x2001), -5);
  // Short request padded with zeros.
  EXPECT_EQ(req({0x40, 0x00, 0x20, 0x00}).size(), 1u);
}

TEST_F(SdoServerTest, LengthMismatchAbortIsConfigurable) {
  EXPECT_EQ(h.write(0x2000, 0, 7, 4), 0x06070012u);
  h.node().policy().sdo.length_mismatch = canopen::SdoAbort::TypeMismatch;
  EXPECT_EQ(h.write(0x2000, 0, 7, 4), 0x06070010u);
  EXPECT_EQ(h.write(0x2003 + 3, 0, 7, 1), 0x06070010u);  // 0x2006 is U64: too short
}

TEST_F(SdoServerTest, HiddenObjectsAnswer06020000BeforeAnyOtherCheck) {
  // A device hides 0x2003 (read-only) and 0x6000 for the moment (its object set follows a mode).
  h.node().od().set_visibility([](std::uint16_t index) { return index != 0x2003 && index != 0x6000; });
  EXPECT_EQ(req({0x40, 0x03, 0x20, 0x00, 0, 0, 0, 0}), Frames{resp({0x80, 0x03, 0x20, 0x00, 0x00, 0x00, 0x02, 0x06})});
  // Write to a read-only hidden object: existence wins over access (0x06010002).
  EXPECT_EQ(req({0x23, 0x03, 0x20, 0x00, 1, 2, 3, 4}), Frames{resp({0x80, 0x03, 0x20, 0x00, 0x00, 0x00, 0x02, 0x06})});
  // Wrong size to a hidden object: existence wins over length (0x06070012).
  EXPECT_EQ(req({0x23, 0x00, 0x60, 0x00, 1, 2, 3, 4}), Frames{resp({0x80, 0x00, 0x60, 0x00, 0x00, 0x00, 0x02, 0x06})});
  // Device code still sees the object; visible objects are unaffected.
  EXPECT_EQ(h.node().od().get<std::uint16_t>(0x6000), 0x1234);
  EXPECT_EQ(req({0x40, 0x00, 0x20, 0x00, 0, 0, 0, 0}), Frames{resp({0x4F, 0x00, 0x20, 0x00, 0x07, 0, 0, 0})});
  h.node().od().set_visibility({});
  EXPECT_EQ(req({0x40, 0x03, 0x20, 0x00, 0, 0, 0, 0}), Frames{resp({0x43, 0x03, 0x20, 0x00, 0xEF, 0xBE, 0xAD, 0xDE})});
}

namespace {
// The generic node plus a data type entry: UNSIGNED8 (0x0005) declared as a dummy type.
canopen::ObjectDictionary od_with_type_definition() {
  auto od = vtest::make_generic_od();
  od.add_object(0x0005, "UNSIGNED8", canopen::ObjectCode::DefType);
  od.add_entry(0x0005, 0, "UNSIGNED8", canopen::DataType::Unsigned32, canopen::Access::Const, 8u);
  return od;
}
}  // namespace

TEST(SdoTypeDefinition, ReadGivesTheLengthAndAWriteIsAnUnsupportedAccess) {
  vtest::CanopenHarness h(od_with_type_definition(), {}, 5);
  h.power_on();
  h.take();
  h.send(0x605, {0x40, 0x05, 0x00, 0x00, 0, 0, 0, 0});
  EXPECT_EQ(h.take(), Frames{resp({0x43, 0x05, 0x00, 0x00, 0x08, 0x00, 0x00, 0x00})});
  h.send(0x605, {0x2F, 0x05, 0x00, 0x00, 0x10, 0, 0, 0});
  EXPECT_EQ(h.take(), Frames{resp({0x80, 0x05, 0x00, 0x00, 0x00, 0x00, 0x01, 0x06})});  // 0x06010000
  // A segmented download is refused the same way, at its initiate.
  h.send(0x605, {0x21, 0x05, 0x00, 0x00, 0x04, 0, 0, 0});
  EXPECT_EQ(h.take(), Frames{resp({0x80, 0x05, 0x00, 0x00, 0x00, 0x00, 0x01, 0x06})});
}

TEST(SdoTypeDefinition, TheAbortCodeIsAKnob) {
  canopen::NodePolicy p;
  p.sdo.type_definition_write = canopen::SdoAbort::ReadOnly;
  vtest::CanopenHarness h(od_with_type_definition(), p, 5);
  h.power_on();
  h.take();
  h.send(0x605, {0x2F, 0x05, 0x00, 0x00, 0x10, 0, 0, 0});
  EXPECT_EQ(h.take(), Frames{resp({0x80, 0x05, 0x00, 0x00, 0x02, 0x00, 0x01, 0x06})});  // 0x06010002
}

TEST(SdoSegmentedExactSize, LenientExpeditedButExactSegmented) {
  canopen::NodePolicy p;
  p.sdo.size_mode = canopen::SdoPolicy::SizeMode::ExcessMustBeZero;
  p.sdo.segmented_exact_size = true;
  vtest::CanopenHarness h(vtest::make_generic_od(), p, 5);
  h.power_on();
  EXPECT_EQ(h.write(0x2000, 0, 7, 4), 0u);                      // expedited: excess zero bytes accepted
  EXPECT_EQ(h.download(0x2000, 0, {7, 0}), 0x06070010u);        // segmented with a size: refused at initiate
  EXPECT_EQ(h.download(0x2006, 0, {1, 2, 3, 4, 5, 6, 7, 8}), 0u);  // exact: fine
}

TEST(SdoServer, WiredFromAboveAnswersThroughItsSender) {
  vtest::FakeNodeLinks links;
  links.status.node_id = 5;
  auto od = vtest::make_generic_od();
  od.reset_range(0x1000, 0x1FFF, 5);  // node-relative COB-IDs for node 5
  canopen::SdoPolicy policy;
  canopen::SdoServer sdo(od, policy, links.status, links);
  sdo.on_request(Frame(0x605, {0x40, 0x00, 0x20, 0x00, 0, 0, 0, 0}).to_can(), sim::Time{});
  EXPECT_EQ(links.sent, Frames{Frame(0x585, {0x4F, 0x00, 0x20, 0x00, 7, 0, 0, 0})});
}
