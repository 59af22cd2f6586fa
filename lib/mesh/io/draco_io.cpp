#include "mesh/io/internal/draco_io.h"

#include <draco/attributes/attribute_quantization_transform.h>
#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <limits>

#include "mesh/io/internal/printable.h"
#include "util/error.h"

namespace proxyvis::detail {
namespace {

// Little-endian base-128 varint as Draco writes counts (at most 5 bytes for 32 bits).
bool readVarint(const std::string& bytes, size_t& pos, uint64_t& value) {
  value = 0;
  for (int shift = 0; shift < 35 && pos < bytes.size(); shift += 7) {
    const auto byte = static_cast<unsigned char>(bytes[pos++]);
    value |= uint64_t(byte & 0x7f) << shift;
    if ((byte & 0x80) == 0) return true;
  }
  return false;
}

// Draco allocates its connectivity from the counts in the header before it reads a face: a
// 305-byte file of bitstream 1.0 made it ask for 5.6 GB (fuzz_draco). Edgebreaker needs about a
// bit per face and a regular grid's positions almost nothing, so 1,000 faces per byte leaves
// real files far inside the bound.
constexpr int64_t kMaxDracoFacesPerByte = 1000;

void checkDeclaredSize(int64_t declared, size_t bytes, const std::string& file) {
  if (declared > kMaxDracoFacesPerByte * int64_t(bytes) + 1000)
    throw Error(file, fmt::format("Draco header declares {} faces in {} bytes", declared, bytes),
                "no encoding holds that many", "the file is corrupt");
}

// A decoder fed corrupt connectivity can still return a mesh; one whose face count differs from
// what the header declares is refused.
void checkFaceCount(int64_t declared, uint32_t decoded, const std::string& file) {
  if (declared >= 0 && uint64_t(declared) != decoded)
    throw Error(file, "Draco mesh decodes to " + std::to_string(decoded) + " faces",
                "its header declares " + std::to_string(declared), "the file is corrupt");
}

// Quantized positions are integers in [0, 2^bits - 1] over the box [origin, origin + range]: a
// value outside, or an origin or range that is not a finite float box, means corrupt data (Draco
// decodes it without complaint: single byte flips gave coordinates of -1.7e38).
void checkQuantization(const draco::PointAttribute& quantized,
                       const draco::AttributeQuantizationTransform& q, const std::string& file) {
  const int bits = q.quantization_bits();
  const int n = quantized.num_components();
  bool box_ok = bits >= 1 && bits <= 30 && std::isfinite(q.range()) && q.range() >= 0 &&
                int(q.min_values().size()) == n;
  for (int c = 0; box_ok && c < n; ++c)
    box_ok = std::isfinite(q.min_value(c)) && std::isfinite(q.min_value(c) + q.range());
  if (!box_ok)
    throw Error(file, "corrupt Draco position quantization",
                fmt::format("{} bits over a range of {:g} from ({:g}, {:g}, {:g}) is not a finite "
                            "box",
                            bits, q.range(), q.min_values().size() > 0 ? q.min_value(0) : 0.f,
                            q.min_values().size() > 1 ? q.min_value(1) : 0.f,
                            q.min_values().size() > 2 ? q.min_value(2) : 0.f),
                "the file is corrupt");
  const int64_t max_value = (int64_t(1) << bits) - 1;
  int32_t v[4] = {0, 0, 0, 0};
  for (draco::AttributeValueIndex i(0); i < uint32_t(quantized.size()); ++i) {
    bool ok = n <= 4 && quantized.ConvertValue<int32_t>(i, n, v);
    for (int c = 0; ok && c < n; ++c) ok = v[c] >= 0 && v[c] <= max_value;
    if (!ok)
      throw Error(file, "Draco position " + std::to_string(i.value()) + " is out of its range",
                  "quantized values must lie in 0.." + std::to_string(max_value) + " (" +
                      std::to_string(bits) + " bits)",
                  "the file is corrupt");
  }
}

// The dequantized positions must keep the spread of the quantized ones: an origin corrupted to
// -1.7e38 (one flipped exponent byte) turns thousands of distinct quantized values into one float,
// which no encoder writes (it takes the origin from the data, at the data's scale). An axis whose
// quantized values span 2 or more steps but dequantize to a single value is refused.
void checkAxesKeepTheirSpread(const draco::PointAttribute& quantized,
                              const draco::PointAttribute& dequantized, const std::string& file) {
  const int n = std::min<int>(quantized.num_components(), 3);
  int32_t q_lo[3], q_hi[3];
  float f_lo[3], f_hi[3];
  for (int c = 0; c < n; ++c) {
    q_lo[c] = std::numeric_limits<int32_t>::max();
    q_hi[c] = std::numeric_limits<int32_t>::min();
    f_lo[c] = std::numeric_limits<float>::infinity();
    f_hi[c] = -std::numeric_limits<float>::infinity();
  }
  for (draco::AttributeValueIndex i(0); i < uint32_t(quantized.size()); ++i) {
    int32_t q[3] = {0, 0, 0};
    float f[3] = {0, 0, 0};
    quantized.ConvertValue<int32_t>(i, int8_t(n), q);
    dequantized.ConvertValue<float>(i, int8_t(n), f);
    for (int c = 0; c < n; ++c) {
      q_lo[c] = std::min(q_lo[c], q[c]);
      q_hi[c] = std::max(q_hi[c], q[c]);
      f_lo[c] = std::min(f_lo[c], f[c]);
      f_hi[c] = std::max(f_hi[c], f[c]);
    }
  }
  for (int c = 0; c < n; ++c) {
    if (quantized.size() > 0 && int64_t(q_hi[c]) - q_lo[c] >= 2 && !(f_hi[c] > f_lo[c]))
      throw Error(file, "corrupt Draco position quantization",
                  fmt::format("quantized values spanning {} steps on axis {} all decode to {:g} "
                              "(the origin is not at the scale of the data)",
                              int64_t(q_hi[c]) - q_lo[c], "xyz"[c], f_lo[c]),
                  "the file is corrupt");
  }
}

}  // namespace

int64_t declaredDracoFaceCount(const std::string& bytes) {
  // "DRACO", version major, minor, encoder type, method, 16-bit flags.
  if (bytes.size() < 11 || bytes.compare(0, 5, "DRACO") != 0) return -1;
  const int major = bytes[5], minor = bytes[6], method = bytes[8];
  const unsigned flags =
      static_cast<unsigned char>(bytes[9]) | (unsigned(static_cast<unsigned char>(bytes[10])) << 8);
  auto u32At = [&](size_t pos) -> int64_t {
    if (pos + 4 > bytes.size()) return -1;
    uint32_t v = 0;
    for (int k = 3; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(bytes[pos + k]);
    return v;
  };
  if (major == 1) {
    // Bitstream 1.x (the draco3d package's bunny.drc is 1.1): fixed-width counts, no metadata
    // (Draco reads it from 1.3 on, whatever the flags say). Sequential: the face count first;
    // edgebreaker: traversal type, new vertices, vertices, faces.
    if (method == 0) return u32At(11);
    return method == 1 ? u32At(20) : -1;
  }
  if (major != 2 || minor != 2) return -1;  // 2.0 and 2.1 are not parsed
  if (flags & 0x8000) return -1;            // metadata comes first and is not parsed here
  size_t pos = 11;
  uint64_t value = 0;
  if (method == 0) return readVarint(bytes, pos, value) ? int64_t(value) : -1;  // sequential
  if (method != 1) return -1;
  ++pos;  // edgebreaker: traversal decoder type, then vertex count and face count
  if (!readVarint(bytes, pos, value) || !readVarint(bytes, pos, value)) return -1;
  return int64_t(value);
}

void decodeDraco(const std::string& bytes, const std::string& file, TriMesh& out) {
  const int64_t declared_faces = declaredDracoFaceCount(bytes);
  checkDeclaredSize(declared_faces, bytes.size(), file);
  draco::DecoderBuffer buffer;
  buffer.Init(bytes.data(), bytes.size());
  auto type = draco::Decoder::GetEncodedGeometryType(&buffer);
  if (!type.ok())
    throw Error(file, "not a Draco file",
                "Draco: " + printableExcerpt(type.status().error_msg_string(), 120),
                "check that the file is a .drc mesh");
  if (type.value() != draco::TRIANGULAR_MESH)
    throw Error(file, "Draco file holds a point cloud, not a triangle mesh", {},
                "encode a mesh (draco_encoder with a mesh input)");
  // Positions are decoded to their quantized integers and dequantized here, so the integers can
  // be checked against the quantization range first (Draco itself does not).
  draco::Decoder decoder;
  decoder.SetSkipAttributeTransform(draco::GeometryAttribute::POSITION);
  auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
  if (!decoded.ok())
    throw Error(file, "cannot decode the Draco mesh",
                "Draco: " + printableExcerpt(decoded.status().error_msg_string(), 120),
                "the file is truncated or corrupt");
  const draco::Mesh& mesh = *decoded.value();
  const draco::PointAttribute* pos = mesh.GetNamedAttribute(draco::GeometryAttribute::POSITION);
  if (pos == nullptr || pos->num_components() < 3)
    throw Error(file, "Draco mesh has no 3D POSITION attribute", {}, "re-encode it with positions");
  // Positions must be numbers: Draco's converter reads a BOOL attribute's bytes as bool, which is
  // undefined behaviour for any byte but 0 and 1 (fuzz_draco, UBSan).
  switch (pos->data_type()) {
    case draco::DT_INT8:
    case draco::DT_UINT8:
    case draco::DT_INT16:
    case draco::DT_UINT16:
    case draco::DT_INT32:
    case draco::DT_UINT32:
    case draco::DT_INT64:
    case draco::DT_UINT64:
    case draco::DT_FLOAT32:
    case draco::DT_FLOAT64:
      break;
    default:
      throw Error(file,
                  "Draco POSITION attribute has data type " +
                      std::to_string(int(pos->data_type())) + ", not a number type",
                  "positions must be integers or floats", "re-encode it with float positions");
  }
  const uint32_t num_points = mesh.num_points();
  checkFaceCount(declared_faces, mesh.num_faces(), file);

  // `values` holds the float positions; `pos` maps points to value indices (the same in both).
  const draco::PointAttribute* values = pos;
  draco::PointAttribute dequantized;
  draco::AttributeQuantizationTransform quantization;
  if (quantization.InitFromAttribute(*pos)) {
    checkQuantization(*pos, quantization, file);
    dequantized.Init(draco::GeometryAttribute::POSITION, pos->num_components(), draco::DT_FLOAT32,
                     false, pos->size());
    if (!quantization.InverseTransformAttribute(*pos, &dequantized))
      throw Error(file, "cannot dequantize the Draco positions", "corrupt quantization data",
                  "the file is corrupt");
    checkAxesKeepTheirSpread(*pos, dequantized, file);
    values = &dequantized;
  }
  out.vertices.resize(num_points);
  for (draco::PointIndex p(0); p < num_points; ++p) {
    float xyz[3] = {0, 0, 0};
    if (!values->ConvertValue<float, 3>(pos->mapped_index(p), xyz))
      throw Error(file, "cannot read Draco positions", "unsupported position data type",
                  "re-encode it with float positions");
    out.vertices[p.value()] = Vec3f(xyz[0], xyz[1], xyz[2]);
  }
  out.triangles.resize(mesh.num_faces());
  for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f) {
    const draco::Mesh::Face& face = mesh.face(f);
    for (int k = 0; k < 3; ++k) {
      const uint32_t i = face[k].value();
      if (i >= num_points)
        throw Error(file, "vertex index out of range",
                    "face " + std::to_string(f.value()) + " references point " + std::to_string(i) +
                        " of " + std::to_string(num_points),
                    "the file is corrupt");
      out.triangles[f.value()][size_t(k)] = i;
    }
  }
}

std::string encodeDraco(const TriMesh& mesh, int quantization_bits, int speed,
                        const std::string& file) {
  if (quantization_bits < 0 || quantization_bits > 30)
    throw Error(file, "bad Draco quantization " + std::to_string(quantization_bits),
                "expected 0 (lossless) or 1..30 bits", "pick e.g. 16");
  draco::Mesh dm;
  dm.set_num_points(uint32_t(mesh.vertices.size()));
  draco::GeometryAttribute ga;
  ga.Init(draco::GeometryAttribute::POSITION, nullptr, 3, draco::DT_FLOAT32, false,
          sizeof(float) * 3, 0);
  const int att_id = dm.AddAttribute(ga, /*identity_mapping=*/true, uint32_t(mesh.vertices.size()));
  draco::PointAttribute* att = dm.attribute(att_id);
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    const float xyz[3] = {mesh.vertices[i].x, mesh.vertices[i].y, mesh.vertices[i].z};
    att->SetAttributeValue(draco::AttributeValueIndex(uint32_t(i)), xyz);
  }
  dm.SetNumFaces(mesh.triangles.size());
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    dm.SetFace(draco::FaceIndex(uint32_t(f)),
               {draco::PointIndex(t[0]), draco::PointIndex(t[1]), draco::PointIndex(t[2])});
  }
  draco::Encoder encoder;
  if (quantization_bits > 0)
    encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, quantization_bits);
  encoder.SetSpeedOptions(speed, speed);
  draco::EncoderBuffer buffer;
  const draco::Status status = encoder.EncodeMeshToBuffer(dm, &buffer);
  if (!status.ok())
    throw WriteError(file, "Draco cannot encode the mesh",
                     "Draco: " + printableExcerpt(status.error_msg_string(), 120),
                     "try another quantization or format");
  return std::string(buffer.data(), buffer.size());
}

}  // namespace proxyvis::detail
