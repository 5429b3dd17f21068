// PNG reading: a round trip, and damaged files refused in one line before the decoder sees them.
#include <gtest/gtest.h>

#include <cstdint>
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

std::uint32_t bigEndian(std::uint32_t v) {
  return (v >> 24) | ((v >> 8) & 0xff00u) | ((v << 8) & 0xff0000u) | (v << 24);
}

// A header declaring 8000 x 8000 pixels in a 57-byte file (the image fuzz target's timeout, as
// a TGA header, which is no longer decoded): refused from the header, before decoding.
TEST(ImageIo, AHeaderDeclaringMorePixelsThanTheFileHoldsIsRefusedAtOnce) {
  std::string png("\x89PNG\r\n\x1a\n", 8);
  const auto chunk = [&png](const char* type, const std::string& data) {
    const std::uint32_t length = bigEndian(std::uint32_t(data.size()));
    png.append(reinterpret_cast<const char*>(&length), 4);
    png += type;
    png += data;
    png.append(4, '\0');  // the CRC, which stb does not check
  };
  std::string header(13, '\0');
  const std::uint32_t side = bigEndian(8000);  // within stb's own 2^30-byte bound
  header.replace(0, 4, reinterpret_cast<const char*>(&side), 4);
  header.replace(4, 4, reinterpret_cast<const char*>(&side), 4);
  header[8] = 8;  // bit depth
  header[9] = 6;  // RGBA
  chunk("IHDR", header);
  chunk("IEND", "");
  const auto bad = std::filesystem::temp_directory_path() / "tissue_image_io_huge.png";
  ASSERT_TRUE(writeTextFileAtomic(bad, png));
  auto read = readImage(bad);
  ASSERT_FALSE(read);
  EXPECT_NE(read.error().message.find("declares 8000 x 8000 pixels, more than a " +
                                      std::to_string(png.size()) + "-byte file can hold"),
            std::string::npos)
      << read.error().message;
  EXPECT_NE(read.error().message.find(bad.string()), std::string::npos);
  EXPECT_EQ(read.error().message.find('\n'), std::string::npos);
  // Not a PNG at all (the fuzz target's TGA): one line saying to give a PNG.
  const auto tga = std::filesystem::temp_directory_path() / "tissue_image_io_huge.tga";
  ASSERT_TRUE(writeTextFileAtomic(tga, std::string("\xff\x00\x03\x00\xff\xff\xff\xff\x00\x00\x00\x00", 12)));
  auto notPng = readImage(tga);
  ASSERT_FALSE(notPng);
  EXPECT_NE(notPng.error().message.find("give a PNG file"), std::string::npos) << notPng.error().message;
}

TEST(ImageIo, AMissingFileSaysSo) {
  auto read = readImage("/nonexistent/tissue.png");
  ASSERT_FALSE(read);
  EXPECT_NE(read.error().message.find("/nonexistent/tissue.png"), std::string::npos);
}

}  // namespace
}  // namespace tissue
