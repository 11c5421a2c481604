// The test helpers of <vplant/test_helpers.h> against the generic EDS node (the CiA 401-style
// fixture tests/data/eds/io_module.eds) and the HLT 1100: SDO transfers of every kind and their
// aborts, NMT frames, PDO layout by the node's current mapping.
#include <gtest/gtest.h>

#include <vplant/simulation.h>
#include <vplant/test_helpers.h>

#include <chrono>
#include <functional>
#include <string>
#include <vector>

using namespace std::chrono_literals;
namespace vt = vplant::test;

namespace {

const std::string kIo = R"(name: io
buses:
  - {name: main, transport: virtual, timing: ideal}
nodes:
  - {name: io, device: eds, eds: eds/io_module.eds, node_id: 5}
  - {name: hlt, device: hlt1100, node_id: 6}
)";

// The plant after its nodes' boot-ups (a request before a node has booted goes unanswered).
vplant::Simulation io_plant() {
  auto sim = vplant::Simulation::load_string(kIo, {}, "io.yaml", VPLANT_TEST_DATA_DIR);
  sim.run_for(5ms);
  return sim;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const vplant::Error& e) {
    return e.what();
  }
  return "(no vplant::Error)";
}

}  // namespace

TEST(SdoClient, ExpeditedUploadReadsTheStoredValue) {
  auto sim = io_plant();
  vt::SdoClient sdo(sim, 5);
  const auto r = sdo.upload(0x1018, 1);
  ASSERT_TRUE(r.ok()) << r.abort_text();
  EXPECT_EQ(r.value(), 0xABCu);
  EXPECT_EQ(r.data, sim.object("io", 0x1018, 1));
}

TEST(SdoClient, SegmentedUploadOfALongString) {
  auto sim = io_plant();
  vt::SdoClient sdo(sim, 5);
  const auto r = sdo.upload(0x1008, 0);
  ASSERT_TRUE(r.ok()) << r.abort_text();
  EXPECT_EQ(r.text(), "vplant IO-16 test module");
}

TEST(SdoClient, ExpeditedAndSegmentedDownloads) {
  auto sim = io_plant();
  vt::SdoClient sdo(sim, 5);
  ASSERT_TRUE(sdo.download(0x1017, 0, vt::le(250, 2)).ok());
  EXPECT_EQ(sim.object("io", 0x1017, 0), (std::vector<std::uint8_t>{250, 0}));

  const std::string label = "recalibrated on the test bench";  // 30 bytes: 5 segments
  const auto r = sdo.download(0x2002, 0, std::vector<std::uint8_t>(label.begin(), label.end()));
  ASSERT_TRUE(r.ok()) << r.abort_text();
  EXPECT_EQ(sdo.upload(0x2002, 0).text(), label);
}

TEST(SdoClient, TheServersAbortCodes) {
  auto sim = io_plant();
  vt::SdoClient sdo(sim, 5);
  const auto missing = sdo.upload(0x1234, 0);
  EXPECT_EQ(missing.abort_code, 0x06020000u);
  EXPECT_TRUE(missing.aborted_by_server);
  EXPECT_NE(missing.abort_text().find("does not exist"), std::string::npos) << missing.abort_text();

  EXPECT_EQ(sdo.download(0x1000, 0, vt::le(1, 4)).abort_code, 0x06010002u);  // read-only
  EXPECT_EQ(sdo.upload(0x2003, 0).abort_code, 0x06010001u);                  // write-only
  EXPECT_EQ(sdo.download(0x2000, 0, vt::le(0, 1)).abort_code, 0x06090032u);  // below LowLimit 1
  // Eight bytes to an UNSIGNED16: the segmented path, refused for its length.
  EXPECT_EQ(sdo.download(0x1017, 0, vt::le(1, 8)).abort_code, 0x06070012u);
  EXPECT_THROW((void)missing.value(), vplant::Error);
}

TEST(SdoClient, ANodeThatIsNotThereTimesOutInVirtualTime) {
  auto sim = io_plant();
  vt::SdoClient sdo(sim, 9, "main", 50ms);
  std::vector<vplant::Frame> seen;
  sim.attach("main", [&](const vplant::Frame& f, vplant::Time) { seen.push_back(f); });
  sim.run_for(5ms);
  seen.clear();
  const auto before = sim.now();
  const auto r = sdo.upload(0x1000, 0);
  EXPECT_EQ(r.abort_code, 0x05040000u);
  EXPECT_FALSE(r.aborted_by_server);
  EXPECT_GE(sim.now() - before, 50ms);
  EXPECT_LE(sim.now() - before, 52ms);
  sim.run_for(1ms);  // the client's abort goes out at the start of the next tick
  // The request, then the client's own abort to the silent server.
  ASSERT_EQ(seen.size(), 2u);
  EXPECT_EQ(seen[0].id, 0x609u);
  EXPECT_EQ(seen[1].id, 0x609u);
  EXPECT_EQ(seen[1].data[0], 0x80);

  EXPECT_NE(error_of([&] { vt::SdoClient(sim, 0); }).find("1..127"), std::string::npos);
  EXPECT_NE(error_of([&] { vt::SdoClient(sim, 5, "no_such_bus"); }).find("no_such_bus"), std::string::npos);
}

TEST(SdoClient, ARequestBeforeTheBootUpGoesUnanswered) {
  auto sim = vplant::Simulation::load_string(kIo, {}, "io.yaml", VPLANT_TEST_DATA_DIR);
  vt::SdoClient sdo(sim, 5, "", 20ms);
  EXPECT_EQ(sdo.upload(0x1000, 0).abort_code, 0x05040000u);  // delivered while the node initialises
  EXPECT_TRUE(sdo.upload(0x1000, 0).ok());
}

TEST(SdoClient, CalledFromAStepItRefusesToNestTheRun) {
  auto sim = io_plant();
  vt::SdoClient sdo(sim, 5);
  std::string error;
  sim.add_step([&](vplant::Time, vplant::Duration) {
    if (error.empty()) error = error_of([&] { (void)sdo.upload(0x1000, 0); });
  });
  sim.run_for(2ms);
  EXPECT_NE(error.find("run_until: called from a step function"), std::string::npos) << error;
}

TEST(Nmt, FramesAndWords) {
  EXPECT_EQ(vt::nmt_frame(vt::Nmt::start, 5), vplant::Frame::make(0, {0x01, 5}));
  EXPECT_EQ(vt::nmt_frame(vt::nmt_command("reset_communication"), 0), vplant::Frame::make(0, {0x82, 0}));
  EXPECT_EQ(vt::nmt_command("pre_operational"), vt::Nmt::pre_operational);
  EXPECT_NE(error_of([] { vt::nmt_command("operational"); }).find("start, stop, pre_operational, reset_node"),
            std::string::npos);
  EXPECT_THROW(vt::nmt_frame(vt::Nmt::stop, 128), vplant::Error);

  auto sim = io_plant();
  auto& bus = sim.attach("main", nullptr);
  EXPECT_EQ(sim.signal("hlt.nmt_state"), 127);
  bus.send(vt::nmt_frame(vt::Nmt::start, 6));
  sim.run_for(2ms);
  EXPECT_EQ(sim.signal("hlt.nmt_state"), 5);
  bus.send(vt::nmt_frame(vt::Nmt::stop, 0));
  sim.run_for(2ms);
  EXPECT_EQ(sim.signal("hlt.nmt_state"), 4);
}

TEST(Pdo, PackedByTheNodesDefaultMappingWithADummyEntry) {
  auto sim = io_plant();
  auto& bus = sim.attach("main", nullptr);
  // RPDO 2: 6411h:01 (16 bits), a dummy byte (0005h), 6411h:02 (16 bits) on 300h + node-ID.
  const auto f = vt::pack_rpdo(sim, "io", 2, {-2, 0, 0x1234});
  EXPECT_EQ(f, vplant::Frame::make(0x305, {0xFE, 0xFF, 0x00, 0x34, 0x12}));
  bus.send(vt::nmt_frame(vt::Nmt::start, 5));
  sim.run_for(2ms);
  bus.send(f);
  sim.run_for(2ms);
  EXPECT_EQ(sim.object("io", 0x6411, 1), (std::vector<std::uint8_t>{0xFE, 0xFF}));
  EXPECT_EQ(sim.object("io", 0x6411, 2), (std::vector<std::uint8_t>{0x34, 0x12}));

  EXPECT_NE(error_of([&] { vt::pack_rpdo(sim, "io", 2, {1, 2}); }).find("maps 3 entries; 2 value(s) given"),
            std::string::npos);
  EXPECT_NE(error_of([&] { vt::pack_rpdo(sim, "io", 2, {70000, 0, 0}); }).find("does not fit mapped entry 1"),
            std::string::npos);
  EXPECT_THROW(vt::pack_rpdo(sim, "io", 3, {}), vplant::Error);      // the node has two RPDOs
  EXPECT_THROW(vt::pack_rpdo(sim, "nobody", 1, {}), vplant::Error);  // no such node
}

TEST(Pdo, FollowsAMappingChangedBySdo) {
  auto sim = io_plant();
  vt::SdoClient sdo(sim, 5);
  // RPDO 1 remapped to one 16-bit entry, on COB-ID 222h.
  ASSERT_TRUE(sdo.download(0x1400, 1, vt::le(0x80000205, 4)).ok());
  EXPECT_NE(error_of([&] { vt::pack_rpdo(sim, "io", 1, {1, 2}); }).find("not valid"), std::string::npos);
  ASSERT_TRUE(sdo.download(0x1600, 0, vt::le(0, 1)).ok());
  ASSERT_TRUE(sdo.download(0x1600, 1, vt::le(0x64110110, 4)).ok());
  ASSERT_TRUE(sdo.download(0x1600, 0, vt::le(1, 1)).ok());
  ASSERT_TRUE(sdo.download(0x1400, 1, vt::le(0x222, 4)).ok());
  EXPECT_EQ(vt::pack_rpdo(sim, "io", 1, {0x4321}), vplant::Frame::make(0x222, {0x21, 0x43}));
}

TEST(Pdo, TpdoFramesSplitByTheMapping) {
  auto sim = io_plant();
  std::vector<vplant::Frame> tpdo1;
  auto& bus = sim.attach("main", [&](const vplant::Frame& f, vplant::Time) {
    if (f.id == 0x185) tpdo1.push_back(f);
  });
  vt::SdoClient sdo(sim, 5);
  ASSERT_TRUE(sdo.download(0x6401, 1, vt::le(1234, 2)).ok());  // rwr: a master may write it
  bus.send(vt::nmt_frame(vt::Nmt::start, 5));
  sim.run_for(2ms);
  bus.send(vplant::Frame::make(0x080, {}));  // SYNC: TPDO 1 has transmission type 1
  sim.run_for(2ms);
  ASSERT_EQ(tpdo1.size(), 1u);
  const auto values = vt::unpack_tpdo(sim, "io", 1, tpdo1[0]);
  ASSERT_EQ(values.size(), 3u);  // 6000h:01, 6000h:02 (8 bits each), 6401h:01 (16 bits)
  EXPECT_EQ(values[2], 1234u);
  EXPECT_EQ(values[0], sim.object("io", 0x6000, 1)[0]);
  EXPECT_THROW(vt::unpack_tpdo(sim, "io", 1, vplant::Frame::make(0x185, {1})), vplant::Error);
}
