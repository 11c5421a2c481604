// WAGDSVC1.eds: generated from the emulated dictionary, committed, identical, and loading in the
// CiA 306 parser without errors or warnings.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "devices/canopen/eds.h"
#include "devices/dsv/product.h"
#include "tests/support/read_file.h"

namespace {
using vtest::read_file;
}  // namespace

TEST(DsvEds, CommittedFilesEqualTheGeneratedOnes) {
  EXPECT_EQ(read_file(VPLANT_SOURCE_DIR "/devices/dsv/WAGDSVC1.eds"), dsv::eds(""));
  EXPECT_EQ(read_file(VPLANT_SOURCE_DIR "/devices/dsv/WAGDSVC1-controller.eds"), dsv::eds("controller"));
}

TEST(DsvEds, ParsesBackWithoutWarnings) {
  for (const std::string variant : {"", "controller"}) {
    const std::string text = dsv::eds(variant);
    EXPECT_TRUE(canopen::check_eds(text, "WAGDSVC1.eds").empty()) << variant;
    canopen::EdsError error;
    std::vector<canopen::EdsError> warnings;
    canopen::EdsFileInfo info;
    auto od = canopen::parse_eds(text, "WAGDSVC1.eds", error, &info, &warnings);
    ASSERT_TRUE(od) << error.to_string();
    EXPECT_TRUE(warnings.empty());
    EXPECT_EQ(od->get<std::uint32_t>(0x1000), 0x00000198u);
    EXPECT_EQ(info.nr_of_rx_pdo, 2);
    EXPECT_EQ(info.nr_of_tx_pdo, 2);
    EXPECT_NE(od->object(0x6343), nullptr);  // every control mode's objects are in the file
    EXPECT_NE(od->object(0x2673), nullptr);
  }
}
