#pragma once
// Image error metrics of docs/design.md ("Error metrics"), on plain float buffers so that
// pv_metrics needs neither the renderer nor OpenImageIO. Images are row-major, interleaved
// channels, linear radiance; the image and its reference must have the same size.
#include <cstddef>
#include <span>
#include <vector>

namespace proxyvis {

// ε of relMSE = mean((I − I_ref)² / (I_ref² + ε)): keeps black reference pixels from dominating.
inline constexpr double kRelMseEpsilon = 1e-2;

// Mean over all pixels and channels of (I − I_ref)². Throws Error if the sizes differ or are 0.
double meanSquaredError(std::span<const float> image, std::span<const float> reference);

// Mean over all pixels and channels of (I − I_ref)² / (I_ref² + epsilon).
double relativeMeanSquaredError(std::span<const float> image, std::span<const float> reference,
                                double epsilon = kRelMseEpsilon);

// Per-pixel squared error averaged over the `channels` channels: one value per pixel
// (image.size() / channels values). The mean of the result equals meanSquaredError().
std::vector<float> squaredErrorPerPixel(std::span<const float> image,
                                        std::span<const float> reference, int channels);

// Per-pixel relative squared error (as in relMSE), averaged over the channels.
std::vector<float> relativeSquaredErrorPerPixel(std::span<const float> image,
                                                std::span<const float> reference, int channels,
                                                double epsilon = kRelMseEpsilon);

}  // namespace proxyvis
