// Image files through the atomic writer: a written EXR and an exact 8-bit PNG
// read back exactly, and a failed write is an ImageFileError that leaves no
// temporary behind.
#include "imaging/image_files.h"

#include "imaging/tests/scratch_folder_test.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace imaging {
namespace {

namespace fs = std::filesystem;

using ImageFilesTest = testing::ScratchFolderTest;

Image gradient() {
  Image image(5, 3, 4);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = float(i) * 0.125f - 1.0f;
  return image;
}

TEST_F(ImageFilesTest, AnExrReadsBackExactlyAndNoTemporaryStays) {
  const Image image = gradient();
  const std::string path = (dir_ / "reference.exr").string();
  writeExr(path, image);
  writePngPreview((dir_ / "reference.png").string(), image);
  const Image back = readExr(path);
  EXPECT_EQ(back.width, image.width);
  EXPECT_EQ(back.height, image.height);
  EXPECT_EQ(back.channels, image.channels);
  EXPECT_EQ(back.pixels, image.pixels);
  EXPECT_EQ(namesInFolder(), (std::vector<std::string>{"reference.exr", "reference.png"}));
}

TEST_F(ImageFilesTest, AnUnknownFormatIsAnImageFileErrorAndLeavesNothing) {
  EXPECT_THROW(writeExr((dir_ / "reference.not-an-image-format").string(), gradient()), ImageFileError);
  EXPECT_TRUE(namesInFolder().empty());
}

TEST_F(ImageFilesTest, AFailedRenameIsAnImageFileErrorAndLeavesNoTemporary) {
  // A folder that is not empty cannot be replaced by the written file.
  const fs::path target = dir_ / "tolerance.exr";
  fs::create_directories(target / "inside");
  EXPECT_THROW(writeExr(target.string(), gradient()), ImageFileError);
  EXPECT_EQ(namesInFolder(), std::vector<std::string>{"tolerance.exr"});
  EXPECT_TRUE(fs::is_directory(target / "inside"));
}

TEST_F(ImageFilesTest, Png8KeepsEveryLevelExactly) {
  // Every 8-bit level once (256 = 16 x 16 x 1), read back as
  // the same bytes: no tone mapping, no sRGB curve.
  std::vector<std::uint8_t> levels(256);
  for (std::size_t i = 0; i < levels.size(); ++i) levels[i] = std::uint8_t(i);
  const fs::path path = dir_ / "levels.png";
  writePng8(path.string(), 16, 16, 1, levels);
  const Image8 read = readImage8(path.string());
  ASSERT_EQ(read.width, 16);
  ASSERT_EQ(read.channels, 1);
  EXPECT_EQ(read.levels, levels);
  EXPECT_EQ(namesInFolder(), std::vector<std::string>{"levels.png"});
}

TEST_F(ImageFilesTest, Png8RefusesAByteCountThatIsNotTheImage) {
  EXPECT_THROW(writePng8((dir_ / "short.png").string(), 4, 4, 3, std::vector<std::uint8_t>(47)), ImageFileError);
  EXPECT_TRUE(namesInFolder().empty());
}

}  // namespace
}  // namespace imaging
