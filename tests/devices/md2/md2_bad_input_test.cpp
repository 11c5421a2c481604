// Bad input never crashes and never moves the MD2's state machine where the manual says it must
// not: wrong control-word sequences, writes in the wrong state, wrong PDO lengths, out-of-range
// values, malformed frames. Each refusal carries the manual's (or CiA 301's) abort code.
#include <random>

#include "tests/devices/md2/md2_fixture.h"

namespace md2test {

TEST_F(Md2Test, WrongControlWordSequencesDoNotMoveTheStateMachine) {
  for (std::uint16_t cw : {0x0002, 0x0004, 0x0006, 0x0008, 0x000A, 0x000C, 0x000E}) {
    ASSERT_EQ(write(0x6040, 0, cw, 2), 0u);
    EXPECT_EQ(status(), 0x0008) << cw;  // INIT: D = 0, nothing happens
  }
  ASSERT_EQ(write(0x6040, 0, 0x0003, 2), 0u);
  ASSERT_EQ(write(0x6040, 0, 0x0006, 2), 0u);  // HOLD: D = 0 alone is no transition
  EXPECT_EQ(status(), 0x000B);
  ASSERT_EQ(write(0x6040, 0, 0x0007, 2), 0u);
  ASSERT_EQ(write(0x6040, 0, 0x000D, 2), 0u);  // ACTIVE: R without a fault, H dropped, M kept
  EXPECT_EQ(status(), 0x000F);
  // In FAULT only a reset edge counts.
  dev->inject_fault("general_error", true);
  h->run_ms(1);
  dev->inject_fault("general_error", false);
  h->run_ms(1);
  for (std::uint16_t cw : {0x0007, 0x0000, 0x0003, 0x0001}) {
    ASSERT_EQ(write(0x6040, 0, cw, 2), 0u);
    EXPECT_EQ(status(), 0x0001) << cw;
  }
  EXPECT_EQ(sdo({0x2B, 0x40, 0x60, 0x00, 0x09, 0x00}),
            (Frames{Frame(0x081, {0, 0, 0, 0, 0, 0, 0, 0}), resp({0x60, 0x40, 0x60, 0x00, 0, 0, 0, 0})}));
  EXPECT_EQ(status(), 0x0009);
}

TEST_F(Md2Test, WritesInTheWrongStateAreRefusedWith08000022) {
  make({}, "controller");
  ASSERT_EQ(write(0x6040, 0, 0x0007, 2), 0u);
  EXPECT_EQ(write(0x6042, 0, 1, 1), 0x08000022u);
  EXPECT_EQ(write(0x6043, 0, 3, 1), 0x08000022u);
  EXPECT_EQ(write(0x604F, 0, 0, 1), 0x08000022u);
  EXPECT_EQ(write(0x2200, 0, 1, 1), 0x08000022u);
  dev->inject_fault("general_error", true);
  h->run_ms(1);
  EXPECT_EQ(status(), 0x0001);
  EXPECT_EQ(write(0x6043, 0, 3, 1), 0x08000022u);  // FAULT is not INIT/DISABLED either
  // The state abort wins over the value abort.
  EXPECT_EQ(write(0x6043, 0, 2, 1), 0x08000022u);
  // Parameters stay writable in every state.
  EXPECT_EQ(write(0x6380, 1, 100, 2), 0u);
  EXPECT_EQ(write(0x1017, 0, 100, 2), 0u);
}

TEST_F(Md2Test, WrongPdoLengths) {
  start();
  h->send(0x201, {0x07, 0x00});  // shorter than the mapping: ignored, no EMCY
  h->send(0x201, {0x07});
  h->send(Frame(0x201, std::vector<std::uint8_t>{}));
  EXPECT_TRUE(h->take().empty());
  EXPECT_EQ(status(), 0x0008);
  h->send(0x201, {0x07, 0x00, 0x00, 0x20, 0xAA, 0xBB, 0xCC, 0xDD});  // longer: extra bytes ignored
  EXPECT_EQ(h->take(), Frames{Frame(0x181, {0x0F, 0x00})});
  h->send(Frame::remote(0x181, 8));  // RTR with the wrong DLC: empty answer
  EXPECT_EQ(h->take(), Frames{Frame(0x181, std::vector<std::uint8_t>{})});
  h->send(Frame::remote(0x201, 4));  // RTR to an RPDO: nothing
  EXPECT_TRUE(h->take().empty());
}

TEST_F(Md2Test, OutOfRangeValues) {
  EXPECT_EQ(write(0x6042, 0, 3, 1), 0x06090031u);
  EXPECT_EQ(write(0x6042, 0, 0, 1), 0x06090032u);
  EXPECT_EQ(write(0x604F, 0, 2, 1), 0x06090031u);
  EXPECT_EQ(write(0x604F, 0, 0xFF, 1), 0x06090032u);
  EXPECT_EQ(write(0x6043, 0, 2, 1), 0x06040043u);   // a gap in the printed set
  EXPECT_EQ(write(0x6043, 0, 10, 1), 0x06090031u);  // above the printed range
  EXPECT_EQ(write(0x6043, 0, 0xF7, 1), 0x06090032u);  // −9
  EXPECT_EQ(write(0x1400, 2, 241, 1), 0x06040043u);
  EXPECT_EQ(write(0x1400, 2, 254, 1), 0x06040043u);  // "only for TPDOs"
  EXPECT_EQ(write(0x1400, 2, 252, 1), 0x06040043u);
  EXPECT_EQ(write(0x1800, 2, 250, 1), 0x06040043u);
  EXPECT_EQ(write(0x1800, 2, 254, 1), 0u);
  EXPECT_EQ(write(0x1005, 0, 0x40000080, 4), 0x06040043u);  // SYNC producer
  EXPECT_EQ(write(0x1003, 0, 5, 1), 0x06040043u);
  EXPECT_EQ(write(0x1011, 2, 0x12345678, 4), 0x08000020u);
  ASSERT_EQ(write(0x1400, 1, 0x80000201, 4), 0u);
  ASSERT_EQ(write(0x1600, 0, 0, 1), 0u);
  EXPECT_EQ(write(0x1600, 0, 5, 1), 0x06090031u);           // only 4 entries
  EXPECT_EQ(write(0x1600, 1, 0x60400008, 4), 0x06040043u);  // length ≠ object size
  EXPECT_EQ(write(0x1600, 1, 0x60410010, 4), 0x06040041u);  // status word is not receivable
  EXPECT_EQ(write(0x1600, 1, 0x20000008, 4), 0x06040041u);  // node address is not mappable
  make({}, "controller");
  EXPECT_EQ(write(0x6600, 1, 2000001, 4), 0x06090031u);
  EXPECT_EQ(write(0x6600, 1, 0xFFFFFFFF, 4), 0x06090032u);
  EXPECT_EQ(write(0x2200, 0, 3, 1), 0x06090031u);
  EXPECT_EQ(write(0x2401, 0, 0xFFFFFFFF, 4), 0x06090032u);
}

TEST_F(Md2Test, MalformedFrames) {
  h->send(0x601, {0x40, 0x00, 0x10, 0x00});  // SDO request shorter than 8 bytes: ignored
  EXPECT_TRUE(h->take().empty());
  EXPECT_EQ(sdo({0xE0, 0x00, 0x10, 0x00}), Frames{resp({0x80, 0x00, 0x10, 0x00, 0x00, 0x00, 0x00, 0x08})});
  EXPECT_EQ(sdo({0xA0, 0x00, 0x10, 0x00}), Frames{resp({0x80, 0x00, 0x10, 0x00, 0x00, 0x00, 0x00, 0x08})});
  EXPECT_EQ(sdo({0x60}), Frames{resp({0x80, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x08})});  // no transfer
  EXPECT_EQ(sdo({0x22, 0x40, 0x60, 0x00, 0x01, 0x00}), Frames{resp({0x60, 0x40, 0x60, 0x00, 0, 0, 0, 0})});
  EXPECT_EQ(status(), 0x0009);  // size not indicated: the object's size is taken
  h->send(0x000, {0x01});  // NMT with DLC 1
  h->send(0x000, {0x55, 0x01});  // unknown command specifier
  h->send(0x000, {0x01, 0x02});  // another node
  h->send(Frame::remote(0x601, 8));
  EXPECT_TRUE(h->take().empty());
  EXPECT_EQ(dev->node().nmt_state(), canopen::NmtState::PreOperational);
  h->send(0x080, {0x01});  // SYNC with a counter byte is accepted (nothing to send in Pre-op)
  EXPECT_TRUE(h->take().empty());
}

TEST_F(Md2Test, RandomFramesNeverCrashAndTheNodeKeepsAnswering) {
  make({}, "controller");
  std::mt19937 rng(408);
  const std::uint32_t ids[] = {0x000, 0x080, 0x181, 0x201, 0x301, 0x401, 0x501, 0x601, 0x701, 0x100, 0x7E5};
  for (int i = 0; i < 20000; ++i) {
    Frame f;
    f.id = ids[rng() % std::size(ids)];
    const auto dlc = rng() % 9;
    if (rng() % 16 == 0) {
      f = Frame::remote(f.id, static_cast<std::uint8_t>(dlc));
    } else {
      for (unsigned b = 0; b < dlc; ++b) f.data.push_back(static_cast<std::uint8_t>(rng()));
    }
    if (f.id == 0x000 && (f.data.size() == 2) && (f.data[0] == 0x81 || f.data[0] == 0x82 || f.data[0] == 0x02)) {
      f.data[1] = 0x7F;  // keep the node reachable: no resets/stops of node 1 by chance
    }
    h->send(f);
    if (i % 100 == 0) h->run_ticks(1);
  }
  h->nmt(0x80, 1);
  h->take();
  EXPECT_EQ(sdo({0x40, 0x00, 0x10, 0x00}), Frames{resp({0x43, 0x00, 0x10, 0x00, 0x98, 0x01, 0x00, 0x10})});
  const auto s = status() & 0x000F;
  EXPECT_TRUE(s == 0x8 || s == 0x9 || s == 0xB || s == 0xF || s == 0x1) << s;
}

}  // namespace md2test
