#pragma once
// The metadata every rendered image carries (render, render-compare): what made it, so that an
// EXR found later says how to make it again. Written as OpenImageIO attributes named
// "proxyvis:<key>" (EXR header attributes; PNG text chunks) and the standard "Software".
#include <cstdint>
#include <string>
#include <vector>

#include "image/image_io.h"
#include "render/renderer.h"
#include "scene/scene_desc.h"

namespace proxyvis {

struct RenderMetadata {
  std::string program;                // "render", "render-compare"
  std::string estimator;              // "exact", "roulette", ...
  int spp = 0;                        // light samples per pixel taken
  double seconds = 0;                 // render time
  uint64_t seed = 0;                  // the renderer's seed (RenderSettings::seed)
  std::vector<ImageAttribute> extra;  // more attributes, e.g. a layer's meaning
};

// proxyvis:estimator, :spp, :seconds, :seed (decimal text: 64 bits), :scene (the file),
// :scene_name, :camera ("eye [x, y, z] look_at [...] up [...] fov_deg f resolution WxH"), :build
// (commit and build type), :version, then `extra`; and Software = "proxyvis <version> <program>".
std::vector<ImageAttribute> renderAttributes(const SceneDesc& scene, const RenderMetadata& m);

// A render's AOVs as one 4-channel image: mean estimated visibility ("visibility.Y") and the
// rays per pixel by kind ("rays.proxy", "rays.original", "rays.probe"), in EXR's layer.channel
// naming so that viewers show them as two layers.
extern const std::vector<std::string> kAovChannelNames;
Image aovImage(const RenderResult& r);

// The camera as one line of text (the :camera attribute).
std::string cameraText(const SceneDesc& scene);

}  // namespace proxyvis
