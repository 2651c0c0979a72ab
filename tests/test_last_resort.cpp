// Faults the program must survive: an exception nobody caught (exit 4 with its message, also from
// another thread), and a write to a full disk (a WriteError naming the file, no file left half
// written).
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <thread>

#include <gtest/gtest.h>

#include "app/last_resort.hpp"
#include "io/durable_file.hpp"

using namespace psph;
namespace fs = std::filesystem;

TEST(LastResort, AnUncaughtExceptionIsExit4WithItsMessage) {
  EXPECT_EXIT(
      {
        install_last_resort();
        std::thread([] { throw std::runtime_error("a bug in a worker"); }).join();
      },
      testing::ExitedWithCode(4), "poresph: internal error: a bug in a worker");
}

TEST(DurableFile, AFullDiskIsAnErrorNamingTheFileAndNothingIsLeft) {
  const fs::path dir = fs::temp_directory_path() / ("poresph_durable_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string path = (dir / "summary.json").string();
  write_file_durably(path, "old\n");
  fs::create_symlink("/dev/full", path + ".partial");  // every write there fails with ENOSPC
  try {
    write_file_durably(path, std::string(1 << 16, 'x'));
    ADD_FAILURE() << "a write to a full disk succeeded";
  } catch (const WriteError& e) {
    EXPECT_NE(std::string(e.what()).find(path + ": writing failed: No space left on device"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(fs::symlink_status(path + ".partial"))) << "the partial file was left behind";
  std::ifstream in(path);
  std::string kept;
  std::getline(in, kept);
  EXPECT_EQ(kept, "old") << "the complete old file was not kept";
  fs::remove_all(dir);
}
