// Image files through OpenImageIO: the metadata every rendered image carries and the AOV layer
// names, read back from the written EXR; errors raised inside the OIIO module (loaded on first
// use, image/oiio_module.h) reach the caller as the same error types.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>

#include "image/image_io.h"
#include "image/oiio_module.h"
#include "render/image_metadata.h"
#include "tests/support/sanitizer_build.h"
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

// EXR goes through OpenEXR (image/exr_io.h), every other format through the OIIO module: the
// two must agree on EXR files, both ways, to the bit. Values cover half's rounding, its range
// (65504 and beyond), denormals, negatives, zero and infinity.
TEST(ImageIo, OpenExrAndOiioWriteAndReadTheSameExr) {
  std::vector<float> values = {0.0f,  -0.0f,    1.0f / 3, 2.0f / 3, 1e-6f, 6e-8f,
                               -1.7f, 65504.0f, 70000.0f, 1e30f,    0.1f,  123.456f};
  values.push_back(std::numeric_limits<float>::infinity());
  values.push_back(0.9999f);
  values.push_back(1.0009765625f);  // 1 + 2^-10: one half ulp above 1
  Image image{5, 3, 3, {}};
  for (const float scale : {1.0f, -2.0f, 0.5f})
    for (const float v : values) image.pixels.push_back(v * scale);
  ASSERT_EQ(image.pixels.size(), 45u);
  for (const bool full : {false, true}) {
    ImageWriteOptions options;
    options.full_float = full;
    options.attributes = {{"proxyvis:spp", 64},
                          {"proxyvis:seconds", 0.25f},
                          {"proxyvis:scene_name", std::string("garden")}};
    const fs::path ours = scratchFile(full ? "ours_float.exr" : "ours_half.exr");
    const fs::path oiio = ours.parent_path() / (full ? "oiio_float.exr" : "oiio_half.exr");
    writeImage(image, ours, options);
    oiioModule().write_image(image, oiio, options);
    const Image a = readImage(ours), b = readImage(oiio);
    const Image a_oiio = oiioModule().read_image(ours), b_oiio = oiioModule().read_image(oiio);
    ASSERT_EQ(a.channels, 3);
    for (const Image* x : {&b, &a_oiio, &b_oiio}) {
      EXPECT_EQ(x->width, a.width);
      EXPECT_EQ(x->height, a.height);
      ASSERT_EQ(x->pixels.size(), a.pixels.size());
      for (size_t i = 0; i < a.pixels.size(); ++i)  // bit for bit (-0 and +0 differ)
        EXPECT_EQ(std::signbit(x->pixels[i]), std::signbit(a.pixels[i])) << i;
      EXPECT_EQ(std::memcmp(x->pixels.data(), a.pixels.data(), a.pixels.size() * 4), 0)
          << (full ? "float" : "half");
    }
    if (full) {
      EXPECT_EQ(a.pixels, image.pixels);
    }
    const ImageHeader h = readImageHeader(ours), h_oiio = oiioModule().read_image_header(ours);
    EXPECT_EQ(h.channel_names, h_oiio.channel_names);
    EXPECT_EQ(h.channel_names, (std::vector<std::string>{"R", "G", "B"}));
    for (const char* key : {"proxyvis:spp", "proxyvis:seconds", "proxyvis:scene_name"})
      EXPECT_EQ(h.attribute(key), h_oiio.attribute(key)) << key;
    EXPECT_EQ(h.attribute("compression"), "");  // not an attribute of ours
    EXPECT_FALSE(h_oiio.attribute("DateTime").empty());
  }
}

// OIIO's order for the channels it reads: unlayered first (R G B A leading), then each layer's.
TEST(ImageIo, ExrChannelsAreReadInOiiosOrder) {
  const fs::path file = scratchFile("layers.exr");
  const Image image{1, 1, 6, {1, 2, 3, 4, 5, 6}};
  ImageWriteOptions options;
  options.full_float = true;
  options.channel_names = {"z.Y", "B", "a.R", "G", "R", "a.G"};
  writeImage(image, file, options);
  EXPECT_EQ(readImageHeader(file).channel_names,
            oiioModule().read_image_header(file).channel_names);
  EXPECT_EQ(readImage(file).pixels, oiioModule().read_image(file).pixels);
  EXPECT_EQ(readImage(file).pixels, (std::vector<float>{5, 4, 2, 3, 6, 1}));  // R G B a.R a.G z.Y
}

// Where the header's attribute sizes are: OpenEXR allocates the size an attribute claims before
// it reads the value (up to 2 GiB for a damaged size byte; the same with OpenImageIO, which reads
// EXR through OpenEXR), so the damage below leaves those four bytes of each attribute alone.
std::vector<bool> attributeSizeBytes(const std::string& exr) {
  std::vector<bool> size_byte(exr.size(), false);
  size_t at = 8;  // magic number and version
  while (at < exr.size() && exr[at] != 0) {
    at = exr.find('\0', at) + 1;  // name
    at = exr.find('\0', at) + 1;  // type
    uint32_t size = 0;
    std::memcpy(&size, &exr[at], 4);
    for (int k = 0; k < 4; ++k) size_byte[at + k] = true;
    at += 4 + size;
  }
  return size_byte;
}

// The EXR reader on damaged files (render-compare reads its cached reference back; a damaged one
// must be refused, never crash): byte flips, truncations and extreme values load or throw Error.
TEST(ImageIo, DamagedExrLoadsOrThrowsError) {
  const fs::path good = scratchFile("good.exr");
  Image image{6, 4, 3, {}};
  for (int i = 0; i < 72; ++i) image.pixels.push_back(0.1f * float(i));
  writeImage(image, good);
  const std::string original = readTextFile(good);
  ASSERT_GT(original.size(), 300u);
  const std::vector<bool> size_byte = attributeSizeBytes(original);
  ASSERT_GE(std::count(size_byte.begin(), size_byte.end(), true), 32);  // the 8 required + capDate
  std::mt19937 rng(5);
  auto position = [&](size_t end) {
    for (;;)
      if (const size_t at = rng() % end; !size_byte[at]) return at;
  };
  // Under ASan a damaged width's allocation (up to 1 GiB, zeroed) costs ~0.3 s: fewer rounds.
  constexpr int kRounds = test::kSanitizerBuild ? 150 : 1500;
  int loaded = 0, refused = 0;
  const fs::path bad = good.parent_path() / "bad.exr";
  for (int round = 0; round < kRounds; ++round) {
    std::string bytes = original;
    const int kind = round % 3;
    if (kind == 0) {  // a few bytes replaced anywhere: names, types, values, offsets, pixels
      for (int k = 1 + int(rng() % 4); k > 0; --k) bytes[position(bytes.size())] = char(rng());
    } else if (kind == 1) {  // cut short
      bytes.resize(rng() % bytes.size());
    } else {  // four bytes of the header (a window, a count, an offset) set to an extreme
      const size_t at = position(300);
      const uint32_t v =
          std::array<uint32_t, 4>{0x7fffffffu, 0x80000000u, 0xffffffffu, 1u << 16}[rng() % 4];
      std::memcpy(&bytes[at], &v, 4);
    }
    {
      std::ofstream out(bad, std::ios::binary | std::ios::trunc);
      out.write(bytes.data(), std::streamsize(bytes.size()));
    }
    try {
      const Image got = readImage(bad);
      EXPECT_EQ(got.pixels.size(), size_t(got.width) * got.height * got.channels);
      readImageHeader(bad);
      ++loaded;
    } catch (const WriteError&) {
      FAIL() << "a read error is not a WriteError";
    } catch (const Error& e) {
      EXPECT_EQ(e.file(), bad.string());
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
      ++refused;
    }
  }
  EXPECT_GT(refused, kRounds / 15);  // both outcomes happen, or this tests nothing
  EXPECT_GT(loaded, kRounds / 150);
  RecordProperty("loaded", loaded);
  RecordProperty("refused", refused);
  EXPECT_EQ(readImage(good).pixels.size(), image.pixels.size());
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
