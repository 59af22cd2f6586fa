#include "mesh/internal/draco_io.h"

#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>

#include "util/error.h"

namespace proxyvis::detail {

void decodeDraco(const std::string& bytes, const std::string& file, TriMesh& out) {
  draco::DecoderBuffer buffer;
  buffer.Init(bytes.data(), bytes.size());
  auto type = draco::Decoder::GetEncodedGeometryType(&buffer);
  if (!type.ok())
    throw Error(file, "not a Draco file", "Draco: " + type.status().error_msg_string(),
                "check that the file is a .drc mesh");
  if (type.value() != draco::TRIANGULAR_MESH)
    throw Error(file, "Draco file holds a point cloud, not a triangle mesh", {},
                "encode a mesh (draco_encoder with a mesh input)");
  draco::Decoder decoder;
  auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
  if (!decoded.ok())
    throw Error(file, "cannot decode the Draco mesh",
                "Draco: " + decoded.status().error_msg_string(),
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

  out.vertices.resize(mesh.num_points());
  for (draco::PointIndex p(0); p < mesh.num_points(); ++p) {
    float xyz[3] = {0, 0, 0};
    if (!pos->ConvertValue<float, 3>(pos->mapped_index(p), xyz))
      throw Error(file, "cannot read Draco positions", "unsupported position data type",
                  "re-encode it with float positions");
    out.vertices[p.value()] = Vec3f(xyz[0], xyz[1], xyz[2]);
  }
  out.triangles.resize(mesh.num_faces());
  for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f) {
    const draco::Mesh::Face& face = mesh.face(f);
    for (int k = 0; k < 3; ++k) {
      const uint32_t i = face[k].value();
      if (i >= mesh.num_points())
        throw Error(file, "vertex index out of range",
                    "face " + std::to_string(f.value()) + " references point " + std::to_string(i) +
                        " of " + std::to_string(mesh.num_points()),
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
    throw WriteError(file, "Draco cannot encode the mesh", "Draco: " + status.error_msg_string(),
                     "try another quantization or format");
  return std::string(buffer.data(), buffer.size());
}

}  // namespace proxyvis::detail
