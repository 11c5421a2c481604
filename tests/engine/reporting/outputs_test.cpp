// Outputs of a run: candump trace, CSV and JUnit XML (the HTML report: tests/engine/reporting/html/).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "tests/support/temp_path.h"
#include "tests/engine/run_helper.h"
#include "tests/support/read_file.h"
#include "tests/engine/test_world.h"

namespace {

using vtest::read_file;

const std::string kRun = vtest::kMachine + R"(
clock: {duration: 1s}
outputs:
  sample_period: 100ms
  csv: {file: OUT/run.csv, signals: [axis.position, "frame(0x185)[0:4] as i32"]}
  junit: OUT/run.xml
  trace: OUT/run.log
script:
  - wait: 10ms
  - nmt: start
  - sync: 100ms
  - rpdo: {node: ax, values: {"0x6001": 100000}}
  - name: never reached
    expect: {signal: axis.position, above: 5, within: 500ms}
)";

}  // namespace

TEST(Outputs, TraceCsvAndJunit) {
  const vtest::TempPath out_dir("vplant-outputs");  // removed with what the run wrote into it
  const std::string& dir = out_dir.str();
  std::string text = kRun;
  for (auto p = text.find("OUT"); p != std::string::npos; p = text.find("OUT")) text.replace(p, 3, dir);
  const auto r = vtest::run_text(text);
  EXPECT_EQ(r.rc, 1);

  const auto csv = read_file(dir + "/run.csv");
  std::istringstream lines(csv);
  std::string header, row0, row5;
  std::getline(lines, header);
  EXPECT_EQ(header, "time_s,axis.position,frame(0x185)[0:4] as i32");
  std::getline(lines, row0);
  EXPECT_EQ(row0, "0.000000,0,nan");
  for (int i = 0; i < 5; ++i) std::getline(lines, row5);
  EXPECT_EQ(row5.substr(0, 9), "0.500000,");
  int rows = 6;
  for (std::string l; std::getline(lines, l);) ++rows;
  EXPECT_EQ(rows, 10);  // samples at 0.0 .. 0.9 s

  const auto trace = read_file(dir + "/run.log");
  // Bit timing at 500 kbit/s: stamps are the ends of the frames' EOF, 2 us per bit after the tick
  // that sent them (boot-up 55 bits, NMT start 65 bits, stuff bits included).
  EXPECT_EQ(trace.substr(0, 32), "(0000000000.000110) main 705#00\n");
  EXPECT_NE(trace.find("(0000000000.010130) main 000#0100\n"), std::string::npos);

  const auto xml = read_file(dir + "/run.xml");
  // The assertion and one test case per rule of the verdict on the master (engine/running/master_monitor.h).
  EXPECT_NE(xml.find("<testsuite name=\"test\" tests=\"12\" failures=\"1\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("name=\"never reached\""), std::string::npos);
  EXPECT_NE(xml.find("expected axis.position &gt; 5 within 0.5 s"), std::string::npos) << xml;
}
