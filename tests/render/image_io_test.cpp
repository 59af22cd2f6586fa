// Image files through OpenImageIO: the metadata every rendered image carries and the AOV layer
// names, read back from the written EXR; errors raised inside the OIIO module (loaded on first
// use, image/oiio_module.h) reach the caller as the same error types.
#include <gtest/gtest.h>

#include <filesystem>

#include "image/image_io.h"
#include "render/image_metadata.h"
#include "util/error.h"
#include "util/input_file.h"

namespace proxyvis {
namespace {

namespace fs = std::filesystem;

fs::path scratchFile(const std::string& name) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::temp_directory_path() / (std::string("pv_image_io_") + info->name());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir / name;
}

SceneDesc smallScene() {
  SceneDesc scene;
  scene.path = "/scenes/garden.json";
  scene.camera.eye = {1, 2, 3};
  scene.camera.look_at = {0, 0.5f, 0};
  scene.camera.fov_deg = 38;
  scene.camera.width = 4;
  scene.camera.height = 2;
  return scene;
}

TEST(ImageIo, RenderMetadataIsReadBack) {
  const fs::path file = scratchFile("meta.exr");
  Image image{4, 2, 3, std::vector<float>(4 * 2 * 3, 0.25f)};
  ImageWriteOptions options;
  RenderMetadata meta{"render",
                      "roulette",
                      64,
                      1.5,
                      18446744073709551615ull,
                      {{"proxyvis:table", std::string("equal-time")}}};
  options.attributes = renderAttributes(smallScene(), meta);
  writeImage(image, file, options);

  const ImageHeader header = readImageHeader(file);
  EXPECT_EQ(header.attribute("proxyvis:estimator"), "roulette");
  EXPECT_EQ(header.attribute("proxyvis:spp"), "64");
  EXPECT_EQ(header.attribute("proxyvis:seconds"), "1.5");
  EXPECT_EQ(header.attribute("proxyvis:seed"), "18446744073709551615");  // all 64 bits
  EXPECT_EQ(header.attribute("proxyvis:scene"), "/scenes/garden.json");
  EXPECT_EQ(header.attribute("proxyvis:scene_name"), "garden");  // no "name": the file's stem
  EXPECT_EQ(header.attribute("proxyvis:camera"),
            "eye [1, 2, 3] look_at [0, 0.5, 0] up [0, 1, 0] fov_deg 38 resolution 4x2");
  EXPECT_EQ(header.attribute("proxyvis:table"), "equal-time");
  EXPECT_FALSE(header.attribute("proxyvis:build").empty());
  EXPECT_FALSE(header.attribute("proxyvis:version").empty());
  EXPECT_EQ(header.attribute("Software").rfind("proxyvis ", 0), 0u);
  EXPECT_EQ(readImage(file).pixels, image.pixels);  // the metadata leaves the pixels alone
}

TEST(ImageIo, AovChannelsAreLayers) {
  const fs::path file = scratchFile("aov.exr");
  RenderResult r;
  r.radiance = Image{2, 1, 3, {1, 2, 3, 4, 5, 6}};
  r.visibility = Image{2, 1, 1, {0.5f, 1}};
  r.cost = Image{2, 1, 3, {7, 8, 9, 10, 11, 12}};
  const Image aov = aovImage(r);
  ASSERT_EQ(aov.channels, 4);
  EXPECT_EQ(aov.pixels, (std::vector<float>{0.5f, 7, 8, 9, 1, 10, 11, 12}));
  ImageWriteOptions options;
  options.full_float = true;
  options.channel_names = kAovChannelNames;
  writeImage(aov, file, options);
  std::vector<std::string> names = readImageHeader(file).channel_names;
  std::sort(names.begin(), names.end());  // EXR stores channels sorted by name
  EXPECT_EQ(names, (std::vector<std::string>{"rays.original", "rays.probe", "rays.proxy",
                                             "visibility.Y"}));
}

TEST(ImageIo, AutoExposureMapsThe99thPercentileToOne) {
  Image image{10, 10, 3, std::vector<float>(300, 0.5f)};
  image.pixels[0] = 1000;  // one hot pixel does not set the exposure
  EXPECT_FLOAT_EQ(autoExposure(image), 2.0f);
  EXPECT_FLOAT_EQ(autoExposure(Image{1, 1, 3, {0, 0, 0}}), 1.0f);
}

// The module throws; the program catches by type: a missing folder is a WriteError (exit 3), an
// unreadable file an Error (exit 2), each naming the file.
TEST(ImageIo, ErrorsFromTheModuleKeepTheirTypeAndFile) {
  const fs::path dir = scratchFile("x").parent_path();
  const Image image{2, 1, 3, std::vector<float>(6, 0.5f)};
  const fs::path unwritable = dir / "no-such-folder" / "a.exr";
  try {
    writeImage(image, unwritable);
    FAIL() << "no error";
  } catch (const WriteError& e) {
    EXPECT_EQ(e.exitCode(), 3);
    EXPECT_NE(std::string(e.what()).find(unwritable.string()), std::string::npos) << e.what();
  }
  const fs::path missing = dir / "missing.exr";
  try {
    readImage(missing);
    FAIL() << "no error";
  } catch (const WriteError&) {
    FAIL() << "a read error is not a WriteError";
  } catch (const Error& e) {
    EXPECT_EQ(e.exitCode(), 2);
    EXPECT_EQ(e.file(), missing.string());
  }
  EXPECT_FALSE(fs::exists(unwritable));
}

// The module writes through this program's writeAtomically, so an input of this run is refused
// as an image output (that register lives in the program, not in the module) and stays intact.
TEST(ImageIo, AnInputOfThisRunIsNotReplacedByAnImage) {
  const fs::path input = scratchFile("input.exr");
  const Image original{2, 1, 3, {0.25f, 0.5f, 1, 2, 4, 8}};
  ImageWriteOptions exact;
  exact.full_float = true;
  writeImage(original, input, exact);
  registerInput(input);
  const Image other{2, 1, 3, std::vector<float>(6, 0.0f)};
  EXPECT_THROW(writeImage(other, input), Error);
  EXPECT_EQ(readImage(input).pixels, original.pixels);
  EXPECT_EQ(std::distance(fs::directory_iterator(input.parent_path()), fs::directory_iterator()),
            1);  // no temporary left
}

}  // namespace
}  // namespace proxyvis
