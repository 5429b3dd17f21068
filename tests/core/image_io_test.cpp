// PNG reading: a round trip, and damaged files refused in one line before the decoder sees them.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tissue/core/atomic_file.h"
#include "tissue/core/image.h"

namespace tissue {
namespace {

std::filesystem::path writeRoundTripPng() {
  Image8 image(3, 2, 4);
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    image.pixels[i] = std::uint8_t(i * 7);
  const auto path = std::filesystem::temp_directory_path() / "tissue_image_io_test.png";
  EXPECT_TRUE(writePng(path, image));
  return path;
}

TEST(ImageIo, RoundTripsAPng) {
  const auto path = writeRoundTripPng();
  auto read = readImage(path, 4);
  ASSERT_TRUE(read) << read.error().message;
  EXPECT_EQ(read->width, 3);
  EXPECT_EQ(read->height, 2);
  for (std::size_t i = 0; i < read->pixels.size(); ++i)
    EXPECT_EQ(read->pixels[i], std::uint8_t(i * 7));
}

TEST(ImageIo, AChunkLongerThanTheFileIsOneLineNamingIt) {
  const auto path = writeRoundTripPng();
  auto bytes = readTextFile(path);
  ASSERT_TRUE(bytes);
  std::string damaged = *bytes;
  damaged[8] = '\x7f';  // the IHDR chunk's length, big-endian: now about 2 GiB
  const auto bad = std::filesystem::temp_directory_path() / "tissue_image_io_bad_chunk.png";
  ASSERT_TRUE(writeTextFileAtomic(bad, damaged));
  auto read = readImage(bad);
  ASSERT_FALSE(read);
  EXPECT_NE(read.error().message.find("chunk 1"), std::string::npos) << read.error().message;
  EXPECT_NE(read.error().message.find(bad.string()), std::string::npos);
  EXPECT_EQ(read.error().message.find('\n'), std::string::npos);
}

TEST(ImageIo, APngCutBeforeItsEndIsRefused) {
  const auto path = writeRoundTripPng();
  auto bytes = readTextFile(path);
  ASSERT_TRUE(bytes);
  const auto cut = std::filesystem::temp_directory_path() / "tissue_image_io_cut.png";
  ASSERT_TRUE(writeTextFileAtomic(cut, bytes->substr(0, bytes->size() - 12)));  // no IEND
  auto read = readImage(cut);
  ASSERT_FALSE(read);
  EXPECT_NE(read.error().message.find("IEND"), std::string::npos) << read.error().message;
}

// The PNG fuzz target's timeout: 18 bytes that stb reads as a 65535 x 65535 TGA, which it
// decoded for minutes. Refused from the header, as more pixels than 18 bytes can hold.
TEST(ImageIo, AHeaderDeclaringMorePixelsThanTheFileHoldsIsRefusedAtOnce) {
  const std::string tga("\xff\x00\x03\x00\xff\xff\xff\xff\x00\x00\x00\x00\x60\x62\xd7\x28\x0f\x67", 18);
  const auto bad = std::filesystem::temp_directory_path() / "tissue_image_io_huge.tga";
  ASSERT_TRUE(writeTextFileAtomic(bad, tga));
  auto read = readImage(bad);
  ASSERT_FALSE(read);
  EXPECT_NE(read.error().message.find("more than a 18-byte file can hold"), std::string::npos)
      << read.error().message;
  EXPECT_NE(read.error().message.find(bad.string()), std::string::npos);
  EXPECT_EQ(read.error().message.find('\n'), std::string::npos);
}

TEST(ImageIo, AMissingFileSaysSo) {
  auto read = readImage("/nonexistent/tissue.png");
  ASSERT_FALSE(read);
  EXPECT_NE(read.error().message.find("/nonexistent/tissue.png"), std::string::npos);
}

}  // namespace
}  // namespace tissue
