// SYNC consumer built without a node: the SYNC goes on as an event, a SYNC of the wrong length
// (0x1019) as an emergency request.
#include "devices/canopen/sync_consumer.h"

#include <gtest/gtest.h>

#include "tests/devices/canopen/fake_node_links.h"
#include "tests/devices/canopen/generic_node.h"

using vtest::Frame;

TEST(SyncConsumer, WiredFromAboveReportsTheSyncAndALengthError) {
  vtest::FakeNodeLinks links;
  links.status.nmt_state = canopen::NmtState::Operational;
  auto od = vtest::make_generic_od(true);  // 0x1019 = 0: SYNC without counter
  canopen::PdoPolicy policy;
  canopen::SyncConsumer sync(od, policy, links.status, links, links, links);
  sync.bind_objects();
  sync.on_frame(Frame(0x080, {0x03}).to_can(), sim::Time{});  // a counter byte it does not expect
  EXPECT_EQ(links.raised, std::vector<std::uint16_t>{0x8240});
  EXPECT_TRUE(links.syncs.empty());
  sync.on_frame(Frame(0x080, std::vector<std::uint8_t>{}).to_can(), sim::Time{});
  EXPECT_EQ(links.cleared, std::vector<std::uint16_t>{0x8240});
  EXPECT_EQ(links.syncs, (std::vector<std::pair<std::uint8_t, std::uint8_t>>{{0, 0}}));
  links.status.nmt_state = canopen::NmtState::Stopped;  // no SYNC in Stopped
  sync.on_frame(Frame(0x080, std::vector<std::uint8_t>{}).to_can(), sim::Time{});
  EXPECT_EQ(sync.count(), 1u);
}
