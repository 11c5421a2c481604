// WAGMD2C1.eds: generated from the emulated dictionary, committed, identical, and loading in the
// CiA 306 parser without errors or warnings.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "devices/canopen/eds.h"
#include "devices/md2/product.h"
#include "tests/support/read_file.h"

namespace {
using vtest::read_file;
}  // namespace

TEST(Md2Eds, CommittedFilesEqualTheGeneratedOnes) {
  EXPECT_EQ(read_file(VPLANT_SOURCE_DIR "/devices/md2/WAGMD2C1.eds"), md2::eds(""));
  EXPECT_EQ(read_file(VPLANT_SOURCE_DIR "/devices/md2/WAGMD2C1-controller.eds"), md2::eds("controller"));
}

TEST(Md2Eds, ParsesBackWithoutWarnings) {
  for (const std::string variant : {"", "controller"}) {
    const std::string text = md2::eds(variant);
    EXPECT_TRUE(canopen::check_eds(text, "WAGMD2C1.eds").empty()) << variant;
    canopen::EdsError error;
    std::vector<canopen::EdsError> warnings;
    canopen::EdsFileInfo info;
    auto od = canopen::parse_eds(text, "WAGMD2C1.eds", error, &info, &warnings);
    ASSERT_TRUE(od) << error.to_string();
    EXPECT_TRUE(warnings.empty());
    EXPECT_EQ(od->get<std::uint32_t>(0x1000), 0x10000198u);
    EXPECT_EQ(od->get<std::uint32_t>(0x1018, 1), 0x14Du);
    EXPECT_EQ(od->get_string(0x6057), "Wandfluh AG");
    EXPECT_EQ(info.nr_of_rx_pdo, 8);
    EXPECT_EQ(info.nr_of_tx_pdo, 8);
    EXPECT_EQ(od->object(0x2200) != nullptr, variant == "controller");  // controller-only objects
    EXPECT_EQ(od->get<std::uint32_t>(0x1600, 1), 0x60400010u);
  }
}
