// The frame decoder, byte by byte: each CiA 301 / CiA 305 service as an engineer reads it.
#include "devices/canopen/frame_decoder.h"

#include <gtest/gtest.h>

#include <map>

namespace {

using canopen::DecodedFrame;
using canopen::Service;
using sim::CanFrame;

/// Node 2 knows 6040:00 (UNSIGNED16) and 6041:00; its RPDO1 on 0x202 maps the control word.
class TwoObjects final : public canopen::DecoderContext {
 public:
  TwoObjects() {
    objects_[{0x6040, 0}] = {"Device control word", canopen::DataType::Unsigned16, {}};
    objects_[{0x6041, 0}] = {"Device status word", canopen::DataType::Unsigned16, {}};
    objects_[{0x6301, 1}] = {"Actual value", canopen::DataType::Integer16, {}};
    objects_[{0x6020, 1}] = {"Position value", canopen::DataType::Integer32, canopen::scaled("mm", 0.1)};
    objects_[{0x6300, 1}] = {"Preset value", canopen::DataType::Integer16, canopen::scaled("%", 100.0 / 16384)};
    rpdo_.node = 2;
    rpdo_.transmit = false;
    rpdo_.number = 1;
    rpdo_.entries = {{0x6040, 0, 16}};
    tpdo_.node = 2;
    tpdo_.transmit = true;
    tpdo_.number = 1;
    tpdo_.entries = {{0x6041, 0, 16}, {0x6301, 1, 16}};
    scaled_.node = 2;
    scaled_.number = 2;
    scaled_.entries = {{0x6020, 1, 32}, {0x6300, 1, 16}};
  }
  const ObjectInfo* object(std::uint8_t node, std::uint16_t index, std::uint8_t sub) const override {
    if (node != 2) return nullptr;
    const auto it = objects_.find({index, sub});
    return it == objects_.end() ? nullptr : &it->second;
  }
  const PdoInfo* pdo(std::uint32_t cob_id) const override {
    if (cob_id == 0x202) return &rpdo_;
    if (cob_id == 0x182) return &tpdo_;
    if (cob_id == 0x282) return &scaled_;
    return nullptr;
  }
  std::string_view emcy_text(std::uint8_t node, std::uint16_t code) const override {
    return node == 2 && code == 0xFF01 ? "solenoid A cable break" : "";
  }

 private:
  std::map<std::pair<std::uint16_t, std::uint8_t>, ObjectInfo> objects_;
  PdoInfo rpdo_, tpdo_, scaled_;
};

DecodedFrame decode(std::uint32_t id, std::initializer_list<std::uint8_t> bytes) {
  static const TwoObjects ctx;
  return canopen::decode_frame(CanFrame::data_frame(id, bytes), ctx);
}

TEST(FrameDecoder, NmtCommandAndTarget) {
  auto d = decode(0x000, {0x01, 0x02});
  EXPECT_EQ(d.service, Service::Nmt);
  EXPECT_EQ(d.node, 2);
  EXPECT_EQ(d.text, "NMT start → node 2");
  EXPECT_EQ(decode(0x000, {0x82, 0x00}).text, "NMT reset_communication → all nodes");
  EXPECT_EQ(decode(0x000, {0x80, 0x05}).text, "NMT pre_operational → node 5");
  EXPECT_EQ(decode(0x000, {0x81}).text, "NMT (short frame)");
}

TEST(FrameDecoder, SyncWithAndWithoutCounter) {
  EXPECT_EQ(decode(0x080, {}).text, "SYNC");
  const auto d = decode(0x080, {0x07});
  EXPECT_EQ(d.service, Service::Sync);
  EXPECT_EQ(d.text, "SYNC counter 7");
}

TEST(FrameDecoder, EmcyCodeMeaningAndRegisterBits) {
  auto d = decode(0x085, {0x30, 0x81, 0x11, 0, 0, 0, 0, 0});
  EXPECT_EQ(d.service, Service::Emcy);
  EXPECT_EQ(d.node, 5);
  EXPECT_EQ(d.text,
            "EMCY node 5 0x8130 life guard error or heartbeat error, error register 0x11 (generic, communication), "
            "data [00 00 00 00 00]");
  EXPECT_EQ(canopen::emcy_code_text(0x8110), "CAN overrun (objects lost)");
  EXPECT_EQ(canopen::emcy_code_text(0x8120), "CAN in error passive mode");
  EXPECT_EQ(canopen::emcy_code_text(0x8140), "recovered from bus off");
  EXPECT_EQ(canopen::emcy_code_text(0x8210), "PDO not processed due to length error");
  EXPECT_EQ(canopen::emcy_code_text(0x8220), "PDO length exceeded");
  EXPECT_EQ(canopen::emcy_code_text(0x8240), "unexpected SYNC data length");
  EXPECT_EQ(canopen::emcy_code_text(0x8250), "RPDO timeout");
  EXPECT_EQ(canopen::emcy_code_text(0xFF00), "device specific");
  EXPECT_EQ(canopen::emcy_code_text(0xFF42), "device specific");
  EXPECT_EQ(canopen::emcy_code_text(0x0000), "error reset / no error");
  // Not in the table: the class it belongs to.
  EXPECT_EQ(canopen::emcy_code_text(0x4210), "device temperature");
  EXPECT_EQ(canopen::emcy_code_text(0x8301), "monitoring");
  EXPECT_EQ(canopen::emcy_code_text(0x0001), "unknown error code");
  EXPECT_EQ(canopen::error_register_text(0x00), "none");
  EXPECT_EQ(canopen::error_register_text(0xA1), "generic, device profile, manufacturer");
}

TEST(FrameDecoder, SdoExpeditedDownloadAndResponseWithObjectName) {
  auto d = decode(0x602, {0x2B, 0x40, 0x60, 0x00, 0x0F, 0x00, 0x00, 0x00});
  EXPECT_EQ(d.service, Service::SdoRx);
  EXPECT_EQ(d.node, 2);
  EXPECT_EQ(d.text, "SDO download 6040:00 Device control word = 0x000F (15)");
  d = decode(0x582, {0x60, 0x40, 0x60, 0x00, 0, 0, 0, 0});
  EXPECT_EQ(d.service, Service::SdoTx);
  EXPECT_EQ(d.text, "SDO download response 6040:00 Device control word: done");
  // Unknown node: no name, 4 bytes.
  EXPECT_EQ(decode(0x603, {0x23, 0x00, 0x10, 0x01, 1, 2, 3, 4}).text, "SDO download 1000:01 = 0x04030201 (67305985)");
}

TEST(FrameDecoder, SdoUploadSegmentsAndToggles) {
  EXPECT_EQ(decode(0x602, {0x40, 0x41, 0x60, 0x00, 0, 0, 0, 0}).text, "SDO upload request 6041:00 Device status word");
  EXPECT_EQ(decode(0x582, {0x4B, 0x41, 0x60, 0x00, 0x37, 0x02, 0, 0}).text,
            "SDO upload response 6041:00 Device status word = 0x0237 (567)");
  EXPECT_EQ(decode(0x582, {0x41, 0x08, 0x10, 0x00, 0x0A, 0, 0, 0}).text, "SDO upload initiate response 1008:00, 10 bytes");
  EXPECT_EQ(decode(0x602, {0x60, 0, 0, 0, 0, 0, 0, 0}).text, "SDO upload segment request toggle 0");
  EXPECT_EQ(decode(0x602, {0x70, 0, 0, 0, 0, 0, 0, 0}).text, "SDO upload segment request toggle 1");
  EXPECT_EQ(decode(0x582, {0x00, 'V', 'P', 'L', 'A', 'N', 'T', '-'}).text,
            "SDO upload segment response toggle 0, 7 bytes [56 50 4C 41 4E 54 2D]");
  EXPECT_EQ(decode(0x582, {0x1B, 'D', 'S', 'V', 0, 0, 0, 0}).text,
            "SDO upload segment response toggle 1, 2 bytes [44 53], last");
  EXPECT_EQ(decode(0x602, {0x21, 0x08, 0x10, 0x00, 0x0A, 0, 0, 0}).text, "SDO download initiate 1008:00, 10 bytes");
  EXPECT_EQ(decode(0x582, {0x30, 0, 0, 0, 0, 0, 0, 0}).text, "SDO download segment response toggle 1");
}

TEST(FrameDecoder, SdoAbortWithCiA301Text) {
  const auto d = decode(0x582, {0x80, 0x40, 0x60, 0x00, 0x11, 0x00, 0x09, 0x06});
  EXPECT_EQ(d.service, Service::SdoTx);
  EXPECT_EQ(d.text, "SDO abort 6040:00 Device control word: 0x06090011 sub-index does not exist");
}

TEST(FrameDecoder, PdosWithMappedObjectsAndValues) {
  auto d = decode(0x202, {0x07, 0x00});
  EXPECT_EQ(d.service, Service::Rpdo);
  EXPECT_EQ(d.pdo, 1);
  EXPECT_EQ(d.text, "RPDO1 node 2: 6040:00 Device control word = 0x0007 (7)");
  d = decode(0x182, {0x0F, 0x00, 0x18, 0xFC});
  EXPECT_EQ(d.service, Service::Tpdo);
  EXPECT_EQ(d.text, "TPDO1 node 2: 6041:00 Device status word = 0x000F (15), 6301:01 Actual value = 0xFC18 (-1000)");
  EXPECT_EQ(canopen::service_name(d.service, d.pdo), "TPDO1");
  // Unmapped: by the pre-defined connection set, raw bytes.
  d = decode(0x285, {0x10, 0x27, 0, 0});
  EXPECT_EQ(d.service, Service::Tpdo);
  EXPECT_EQ(d.pdo, 2);
  EXPECT_EQ(d.text, "TPDO2 node 5 [10 27 00 00]");
  EXPECT_EQ(decode(0x182, {0x0F}).text, "TPDO1 node 2: (frame too short)");
  EXPECT_EQ(decode(0x182, {0x0F, 0x00, 0x01}).text, "TPDO1 node 2: 6041:00 Device status word = 0x000F (15), (frame too short)");
  EXPECT_EQ(decode(0x505, {0x01}).text, "RPDO4 node 5 [01]");
  EXPECT_EQ(decode(0x485, {0x01}).pdo, 4);
}

TEST(FrameDecoder, PdoValuesInTheProductsDocumentedUnits) {
  // 6020:01 = 1234 steps of 0.1 mm, 6300:01 = -8192 of ±16384 = ±100 %.
  EXPECT_EQ(decode(0x282, {0xD2, 0x04, 0x00, 0x00, 0x00, 0xE0}).text,
            "TPDO2 node 2: 6020:01 Position value = 123.4 mm (raw 1234), 6300:01 Preset value = -50.000 % (raw -8192)");
  EXPECT_EQ(decode(0x602, {0x2B, 0x00, 0x63, 0x01, 0x00, 0x40, 0, 0}).text,
            "SDO download 6300:01 Preset value = 100.000 % (raw 16384)");
}

TEST(FrameDecoder, HeartbeatConsumerTimesOf1016h) {
  // 1016h:01 = node 5, 500 ms (0x000501F4).
  EXPECT_EQ(decode(0x602, {0x23, 0x16, 0x10, 0x01, 0xF4, 0x01, 0x05, 0x00}).text,
            "SDO download 1016:01 = node 5, 500 ms (0x000501F4)");
  EXPECT_EQ(decode(0x582, {0x43, 0x16, 0x10, 0x02, 0x00, 0x00, 0x00, 0x00}).text,
            "SDO upload response 1016:02 = off (node 0, 0 ms) (0x00000000)");
  EXPECT_EQ(decode(0x582, {0x4F, 0x16, 0x10, 0x00, 0x01, 0, 0, 0}).text, "SDO upload response 1016:00 = 0x01 (1)");
  EXPECT_EQ(canopen::heartbeat_consumer_text(0x007F03E8), "node 127, 1000 ms");
}

TEST(FrameDecoder, ProductEmcyCodesAndTheNeutralReset) {
  EXPECT_EQ(decode(0x082, {0x01, 0xFF, 0x81, 0, 0, 0, 0, 0}).text,
            "EMCY node 2 0xFF01 solenoid A cable break, error register 0x81 (generic, manufacturer), data [00 00 00 00 00]");
  // Another node with the same code: the CiA 301 class.
  EXPECT_EQ(decode(0x083, {0x01, 0xFF, 0x81}).text, "EMCY node 3 0xFF01 device specific, error register 0x81 (generic, manufacturer)");
  EXPECT_EQ(decode(0x082, {0x00, 0x00, 0x00, 0, 0, 0, 0, 0}).text,
            "EMCY node 2 0x0000 error reset / no error, error register 0x00 (none), data [00 00 00 00 00]");
}

TEST(FrameDecoder, SpacedHexBytes) {
  const std::uint8_t bytes[] = {0x2B, 0x40, 0x60, 0x00, 0x0F, 0x00, 0x00, 0x00};
  EXPECT_EQ(canopen::spaced_hex(bytes, 8), "2B 40 60 00 0F 00 00 00");
  EXPECT_EQ(canopen::spaced_hex(bytes, 0), "");
}

TEST(FrameDecoder, HeartbeatBootUpAndGuarding) {
  auto d = decode(0x705, {0x00});
  EXPECT_EQ(d.service, Service::Heartbeat);
  EXPECT_EQ(d.text, "boot-up node 5");
  EXPECT_EQ(decode(0x705, {0x05}).text, "heartbeat node 5 OPERATIONAL");
  EXPECT_EQ(decode(0x705, {0x7F}).text, "heartbeat node 5 PRE-OPERATIONAL");
  EXPECT_EQ(decode(0x705, {0x04}).text, "heartbeat node 5 STOPPED");
  EXPECT_EQ(decode(0x705, {0x85}).text, "node guarding response node 5 toggle 1 OPERATIONAL");
  EXPECT_EQ(canopen::decode_frame(CanFrame::remote_frame(0x705, 1)).text, "node guarding request → node 5");
}

TEST(FrameDecoder, LssAndTime) {
  auto d = decode(0x7E5, {0x04, 0x01, 0, 0, 0, 0, 0, 0});
  EXPECT_EQ(d.service, Service::Lss);
  EXPECT_EQ(d.text, "LSS switch state global: configuration");
  EXPECT_EQ(decode(0x7E5, {0x11, 0x0A, 0, 0, 0, 0, 0, 0}).text, "LSS configure node-ID 10");
  EXPECT_EQ(decode(0x7E4, {0x11, 0x00, 0, 0, 0, 0, 0, 0}).text, "LSS response configure node-ID: success");
  EXPECT_EQ(decode(0x7E4, {0x5A, 0x44, 0x33, 0x22, 0x11, 0, 0, 0}).text, "LSS response inquire vendor-ID = 0x11223344");
  // 12:00:00.000 on day 1: 43200000 ms.
  d = decode(0x100, {0x00, 0x2E, 0x93, 0x02, 0x01, 0x00});
  EXPECT_EQ(d.service, Service::Time);
  EXPECT_EQ(d.text, "TIME 12:00:00.000, day 1 since 1984-01-01");
}

TEST(FrameDecoder, OtherFrames) {
  EXPECT_EQ(decode(0x77F, {0x05}).text, "heartbeat node 127 OPERATIONAL");
  auto ext = CanFrame::data_frame(0x18FF0001, {0xAA});
  ext.extended = true;
  EXPECT_EQ(canopen::decode_frame(ext).text, "extended frame 0x18FF0001 [AA]");
  EXPECT_EQ(decode(0x001, {0x01}).service, Service::Other);
  EXPECT_EQ(decode(0x001, {0x01}).text, "COB-ID 0x001 [01]");
}

}  // namespace
