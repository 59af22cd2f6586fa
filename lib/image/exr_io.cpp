#include "image/exr_io.h"

#include <Iex.h>
#include <Imath/half.h>
#include <ImfChannelList.h>
#include <ImfFloatAttribute.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfIntAttribute.h>
#include <ImfOutputFile.h>
#include <ImfStandardAttributes.h>
#include <ImfStringAttribute.h>
#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <ctime>
#include <tuple>
#include <utility>

#include "util/error.h"
#include "util/lower_case.h"

namespace proxyvis {

namespace {

// OIIO's default names for channels that the caller did not name.
std::string defaultChannelName(int c, int channels) {
  static const char* const kRgba[] = {"R", "G", "B", "A"};
  if (channels == 1) return "Y";
  return c < 4 ? kRgba[c] : fmt::format("channel{}", c);
}

// The key that puts channels in OIIO's order: unlayered first, then by layer; R G B A (or Y)
// first within a layer; then by name.
std::tuple<bool, std::string, int, std::string> channelOrder(const std::string& name) {
  const size_t dot = name.rfind('.');
  const std::string layer = dot == std::string::npos ? "" : name.substr(0, dot);
  const std::string base = dot == std::string::npos ? name : name.substr(dot + 1);
  static const char* const kLeading[] = {"R", "G", "B", "A", "Y"};
  int rank = 5;
  for (int i = 0; i < 5; ++i)
    if (base == kLeading[i]) rank = i;
  return {!layer.empty(), layer, rank, name};
}

std::vector<std::string> orderedChannels(const Imf::Header& header) {
  std::vector<std::string> names;
  for (auto it = header.channels().begin(); it != header.channels().end(); ++it)
    names.emplace_back(it.name());
  std::sort(names.begin(), names.end(), [](const std::string& a, const std::string& b) {
    return channelOrder(a) < channelOrder(b);
  });
  return names;
}

Imf::Compression compressionNamed(const std::string& name, const std::filesystem::path& target) {
  static const std::pair<const char*, Imf::Compression> kNames[] = {
      {"none", Imf::NO_COMPRESSION},   {"rle", Imf::RLE_COMPRESSION},
      {"zips", Imf::ZIPS_COMPRESSION}, {"zip", Imf::ZIP_COMPRESSION},
      {"piz", Imf::PIZ_COMPRESSION},   {"pxr24", Imf::PXR24_COMPRESSION},
      {"b44", Imf::B44_COMPRESSION},   {"b44a", Imf::B44A_COMPRESSION},
      {"dwaa", Imf::DWAA_COMPRESSION}, {"dwab", Imf::DWAB_COMPRESSION}};
  for (const auto& [n, c] : kNames)
    if (name == n) return c;
  throw WriteError(target.string(), "cannot write image", "unknown EXR compression '" + name + "'");
}

std::string nowAsCapDate() {
  const std::time_t t = std::time(nullptr);
  std::tm local{};
  localtime_r(&t, &local);
  char text[32];
  std::strftime(text, sizeof text, "%Y:%m:%d %H:%M:%S", &local);
  return text;
}

// A header may claim any data window: its size, or an Error naming the file when it is empty or
// larger than any image proxyvis writes (2^28 values, 1 GiB as floats: an 8K x 8K RGBA render),
// before anything is allocated for it.
std::pair<int, int> readableSize(const Imath::Box2i& window, size_t channels,
                                 const std::filesystem::path& path) {
  constexpr int64_t kMaxValues = int64_t(1) << 28;
  const int64_t width = int64_t(window.max.x) - window.min.x + 1;
  const int64_t height = int64_t(window.max.y) - window.min.y + 1;
  if (width <= 0 || height <= 0 || channels == 0 || width * height > kMaxValues / int64_t(channels))
    throw Error(path.string(), "cannot read image",
                fmt::format("its header claims {} x {} pixels of {} channels, more than the {} "
                            "values proxyvis reads",
                            width, height, channels, kMaxValues),
                "the file is damaged or not one proxyvis wrote");
  return {int(width), int(height)};
}

// OpenEXR reports everything by exception; each becomes an Error naming the file.
template <typename F>
auto readingExr(const std::filesystem::path& path, F&& read) {
  try {
    return read();
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error(path.string(), "cannot read image", e.what());
  }
}

}  // namespace

bool isExrPath(const std::filesystem::path& path) {
  return lowerExtension(path) == ".exr";
}

void writeExr(const Image& image, const std::filesystem::path& file,
              const ImageWriteOptions& options, const std::filesystem::path& target) {
  try {
    Imf::Header header(image.width, image.height);
    header.compression() = compressionNamed(options.exr_compression, target);
    // OpenEXR writes a slice of the channel's own type: half channels get a half copy.
    const Imf::PixelType type = options.full_float ? Imf::FLOAT : Imf::HALF;
    std::vector<Imath::half> halves;
    if (type == Imf::HALF) halves.assign(image.pixels.begin(), image.pixels.end());
    char* const base = type == Imf::HALF
                           ? reinterpret_cast<char*>(halves.data())
                           : reinterpret_cast<char*>(const_cast<float*>(image.pixels.data()));
    const size_t value_size = type == Imf::HALF ? sizeof(Imath::half) : sizeof(float);
    const size_t x_stride = value_size * image.channels;
    Imf::FrameBuffer frame;
    for (int c = 0; c < image.channels; ++c) {
      const std::string name = options.channel_names.empty() ? defaultChannelName(c, image.channels)
                                                             : options.channel_names[c];
      header.channels().insert(name, Imf::Channel(type));
      frame.insert(name, Imf::Slice(type, base + c * value_size, x_stride, x_stride * image.width));
    }
    Imf::addCapDate(header, nowAsCapDate());
    for (const ImageAttribute& a : options.attributes) {
      if (const int* i = std::get_if<int>(&a.value))
        header.insert(a.name, Imf::IntAttribute(*i));
      else if (const float* f = std::get_if<float>(&a.value))
        header.insert(a.name, Imf::FloatAttribute(*f));
      else
        header.insert(a.name, Imf::StringAttribute(std::get<std::string>(a.value)));
    }
    Imf::OutputFile out(file.c_str(), header);
    out.setFrameBuffer(frame);
    out.writePixels(image.height);
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw WriteError(target.string(), "cannot write image", e.what());
  }
}

ImageHeader readExrHeader(const std::filesystem::path& path) {
  return readingExr(path, [&] {
    Imf::InputFile file(path.c_str());
    const Imf::Header& h = file.header();
    ImageHeader header;
    header.channel_names = orderedChannels(h);
    std::tie(header.width, header.height) =
        readableSize(h.dataWindow(), header.channel_names.size(), path);
    for (auto it = h.begin(); it != h.end(); ++it) {
      const std::string name = it.name() == std::string("capDate") ? "DateTime" : it.name();
      const Imf::Attribute& a = it.attribute();
      if (const auto* s = dynamic_cast<const Imf::StringAttribute*>(&a))
        header.attributes.emplace_back(name, s->value());
      else if (const auto* i = dynamic_cast<const Imf::IntAttribute*>(&a))
        header.attributes.emplace_back(name, std::to_string(i->value()));
      else if (const auto* f = dynamic_cast<const Imf::FloatAttribute*>(&a))
        header.attributes.emplace_back(name, fmt::format("{}", f->value()));
    }
    return header;
  });
}

Image readExr(const std::filesystem::path& path) {
  return readingExr(path, [&] {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i window = file.header().dataWindow();
    const std::vector<std::string> names = orderedChannels(file.header());
    Image image{0, 0, int(names.size()), {}};
    std::tie(image.width, image.height) = readableSize(window, names.size(), path);
    // Checked against the chunk offsets it read with the header: a damaged size claims chunks
    // the file does not have, and is refused before its pixels are allocated.
    if (!file.isComplete())
      throw Error(path.string(), "cannot read image", "some of its pixel chunks are missing",
                  "the file is damaged or was cut short");
    const size_t x_stride = sizeof(float) * image.channels;
    const size_t y_stride = x_stride * image.width;
    image.pixels.resize(size_t(image.width) * image.height * image.channels);
    Imf::FrameBuffer frame;
    for (int c = 0; c < image.channels; ++c)  // the first pixel is the data window's corner
      frame.insert(names[c], Imf::Slice::Make(Imf::FLOAT, image.pixels.data() + c, window, x_stride,
                                              y_stride));
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    return image;
  });
}

}  // namespace proxyvis
