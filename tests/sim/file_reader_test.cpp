#include "sim/file_reader.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>

#include "tests/support/temp_path.h"

using sim::ReadStatus;

TEST(FileReader, ReadsARegularFileWhole) {
  const vtest::TempPath path("file-reader", ".txt");
  std::ofstream(path.str(), std::ios::binary) << std::string(70000, 'x') << "end";
  std::string text, reason;
  ASSERT_EQ(sim::read_input_file(path, text, reason), ReadStatus::Ok) << reason;
  EXPECT_EQ(text.size(), 70003u);
  EXPECT_EQ(text.substr(70000), "end");
}

TEST(FileReader, AMissingFileIsMissingNotAnError) {
  const vtest::TempPath path("file-reader-missing");
  std::string text, reason;
  EXPECT_EQ(sim::read_input_file(path, text, reason), ReadStatus::Missing);
}

TEST(FileReader, ADirectoryIsRefused) {
  const vtest::TempPath dir("file-reader-dir");
  ASSERT_EQ(::mkdir(dir.c_str(), 0700), 0);
  std::string text, reason;
  EXPECT_EQ(sim::read_input_file(dir, text, reason), ReadStatus::Failed);
  EXPECT_EQ(reason, "not a regular file (a directory)");
}

// Without a writer, a blocking open() of a FIFO never returns: this test would hang.
TEST(FileReader, AFifoIsRefusedWithoutBlocking) {
  const vtest::TempPath dir("file-reader-fifo");
  ASSERT_EQ(::mkdir(dir.c_str(), 0700), 0);
  const std::string fifo = dir.str() + "/input.eds";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string text, reason;
  EXPECT_EQ(sim::read_input_file(fifo, text, reason), ReadStatus::Failed);
  EXPECT_EQ(reason, "not a regular file (a FIFO)");
}

// /dev/zero never ends: reading it until EOF grows without bound.
TEST(FileReader, ADeviceIsRefused) {
  std::string text, reason;
  EXPECT_EQ(sim::read_input_file("/dev/zero", text, reason), ReadStatus::Failed);
  EXPECT_EQ(reason, "not a regular file (a character device)");
  EXPECT_TRUE(text.empty());
}

TEST(FileReader, AFileAboveTheLimitIsRefused) {
  const vtest::TempPath path("file-reader-big");
  std::ofstream(path.str(), std::ios::binary) << std::string(1001, 'x');
  std::string text, reason;
  EXPECT_EQ(sim::read_input_file(path, text, reason, 1000), ReadStatus::Failed);
  EXPECT_EQ(reason, "larger than 1000 bytes (the limit for input files)");
  EXPECT_EQ(sim::read_input_file(path, text, reason, 1001), ReadStatus::Ok);
}
