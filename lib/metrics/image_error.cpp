#include "metrics/image_error.h"

#include <string>

#include "util/error.h"

namespace proxyvis {

namespace {

void checkSameSize(std::span<const float> image, std::span<const float> reference) {
  if (image.empty() || image.size() != reference.size())
    throw Error({}, "cannot compare images",
                "sizes differ (" + std::to_string(image.size()) + " vs " +
                    std::to_string(reference.size()) + " values) or are empty",
                "render the image and the reference at the same resolution");
}

void checkChannels(std::span<const float> image, int channels) {
  if (channels <= 0 || image.size() % size_t(channels) != 0)
    throw Error({}, "cannot compute per-pixel errors",
                std::to_string(image.size()) + " values are not a whole number of " +
                    std::to_string(channels) + "-channel pixels");
}

// Shared loop of the per-pixel maps: `term(i)` is the error of value i.
template <typename Term>
std::vector<float> averagePerPixel(size_t values, int channels, Term term) {
  std::vector<float> out(values / size_t(channels));
  for (size_t p = 0; p < out.size(); ++p) {
    double sum = 0;
    for (int c = 0; c < channels; ++c) sum += term(p * size_t(channels) + size_t(c));
    out[p] = float(sum / channels);
  }
  return out;
}

double squaredDifference(float a, float b) {
  double d = double(a) - double(b);
  return d * d;
}

}  // namespace

double meanSquaredError(std::span<const float> image, std::span<const float> reference) {
  checkSameSize(image, reference);
  double sum = 0;
  for (size_t i = 0; i < image.size(); ++i) sum += squaredDifference(image[i], reference[i]);
  return sum / double(image.size());
}

double relativeMeanSquaredError(std::span<const float> image, std::span<const float> reference,
                                double epsilon) {
  checkSameSize(image, reference);
  double sum = 0;
  for (size_t i = 0; i < image.size(); ++i) {
    double r = reference[i];
    sum += squaredDifference(image[i], reference[i]) / (r * r + epsilon);
  }
  return sum / double(image.size());
}

std::vector<float> squaredErrorPerPixel(std::span<const float> image,
                                        std::span<const float> reference, int channels) {
  checkSameSize(image, reference);
  checkChannels(image, channels);
  return averagePerPixel(image.size(), channels,
                         [&](size_t i) { return squaredDifference(image[i], reference[i]); });
}

std::vector<float> relativeSquaredErrorPerPixel(std::span<const float> image,
                                                std::span<const float> reference, int channels,
                                                double epsilon) {
  checkSameSize(image, reference);
  checkChannels(image, channels);
  return averagePerPixel(image.size(), channels, [&](size_t i) {
    double r = reference[i];
    return squaredDifference(image[i], reference[i]) / (r * r + epsilon);
  });
}

}  // namespace proxyvis
