#include "planet/core/input_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <future>

namespace globe {
namespace {

namespace fs = std::filesystem;

fs::path scratchDir() {
  fs::path dir = fs::temp_directory_path() / ("globe_input_file_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

TEST(InputFile, ReadsARegularFile) {
  const fs::path file = scratchDir() / "a.toml";
  std::ofstream(file) << "radius_m = 1\n";
  Result<std::string> text = readInputFile(file.string(), "planet file");
  ASSERT_TRUE(text.ok()) << text.error().format();
  EXPECT_EQ(*text, "radius_m = 1\n");
}

TEST(InputFile, RefusesAFifoWithoutBlocking) {
  const fs::path fifo = scratchDir() / "f.toml";
  fs::remove(fifo);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // Without a writer, a blocking open would never return: run it aside and time it out.
  auto read = std::async(std::launch::async, [&] { return readInputFile(fifo.string(), "planet file"); });
  ASSERT_EQ(read.wait_for(std::chrono::seconds(10)), std::future_status::ready) << "blocked on the FIFO";
  Result<std::string> text = read.get();
  ASSERT_FALSE(text.ok());
  EXPECT_EQ(text.error().file, fifo.string());
  EXPECT_NE(text.error().message.find("a FIFO"), std::string::npos) << text.error().message;
}

TEST(InputFile, RefusesADirectoryAndADevice) {
  Result<std::string> dir = readInputFile(scratchDir().string(), "planet file");
  ASSERT_FALSE(dir.ok());
  EXPECT_NE(dir.error().message.find("a directory"), std::string::npos) << dir.error().message;
  Result<std::string> zero = readInputFile("/dev/zero", "planet file");
  ASSERT_FALSE(zero.ok());
  EXPECT_EQ(zero.error().format(), "/dev/zero: cannot read planet file: it is a device");
}

TEST(InputFile, RefusesAFileOverTheLimit) {
  const fs::path file = scratchDir() / "big.path";
  std::ofstream(file) << std::string(2048, 'x');
  Result<std::string> text = readInputFile(file.string(), "camera path file", 1024);
  ASSERT_FALSE(text.ok());
  EXPECT_NE(text.error().message.find("larger than the limit"), std::string::npos) << text.error().message;
  EXPECT_TRUE(readInputFile(file.string(), "camera path file", 4096).ok());
}

TEST(InputFile, NamesAMissingFileAndTheReason) {
  Result<std::string> text = readInputFile("/nonexistent/p.toml", "planet file");
  ASSERT_FALSE(text.ok());
  EXPECT_EQ(text.error().format(), "/nonexistent/p.toml: cannot open planet file: No such file or directory");
}

}  // namespace
}  // namespace globe
