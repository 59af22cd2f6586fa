// The .sha256 sidecar: every saveMesh leaves one in sha256sum's format, loadMesh refuses a file
// whose content no longer matches it (the only way to notice most corrupted Draco files), and a
// sidecar that is not a regular file or not a sha256sum line is an Error, never a hang.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdlib>

#include "mesh/io/mesh_io.h"
#include "mesh/validation.h"
#include "mesh_test_util.h"
#include "util/error.h"
#include "util/sha256.h"

namespace proxyvis::test {
namespace {
namespace fs = std::filesystem;

// Loads `path` expecting an Error whose file is `named` and whose message contains `fragment`.
void expectRefused(const fs::path& path, const fs::path& named, const std::string& fragment) {
  try {
    loadMesh(path);
    ADD_FAILURE() << path << " loaded but should fail with '" << fragment << "'";
  } catch (const Error& e) {
    EXPECT_EQ(e.file(), named.string());
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    EXPECT_EQ(e.exitCode(), kExitBadInput);
  }
}

TEST(Sidecar, EverySaveWritesOneInSha256sumFormat) {
  ScratchDir dir("sidecar_save");
  for (const char* name : {"cube.ply", "cube.obj", "cube.off", "cube.drc"}) {
    saveMesh(unitCube(), dir / name);
    const std::string sidecar = readBytes(dir / (std::string(name) + ".sha256"));
    EXPECT_EQ(sidecar, sha256Hex(readBytes(dir / name)) + "  " + name + "\n") << name;
  }
  // sha256sum itself accepts them (the format is its own, not a look-alike).
  const std::string command = "cd '" + dir.path().string() + "' && sha256sum --quiet -c " +
                              "cube.ply.sha256 cube.obj.sha256 cube.off.sha256 cube.drc.sha256";
  EXPECT_EQ(std::system(command.c_str()), 0);
  size_t files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir.path())) ++files;
  EXPECT_EQ(files, 8u);  // four meshes, four sidecars, no temporaries
}

TEST(Sidecar, ChangedContentIsRefusedAndLoadsWithoutTheSidecar) {
  ScratchDir dir("sidecar_changed");
  saveMesh(unitCube(), dir / "cube.off");
  EXPECT_EQ(loadMesh(dir / "cube.off").numTriangles(), 12u);
  // Still a valid OFF file, only one coordinate differs: no format check can notice.
  std::string bytes = readBytes(dir / "cube.off");
  const size_t one = bytes.find('1', bytes.find('\n', bytes.find('\n') + 1));
  ASSERT_NE(one, std::string::npos);
  bytes[one] = '2';
  writeBytes(dir / "cube.off", bytes);
  expectRefused(dir / "cube.off", dir / "cube.off", "content does not match its .sha256 sidecar");
  fs::remove(dir / "cube.off.sha256");
  EXPECT_EQ(loadMesh(dir / "cube.off").numTriangles(), 12u);
}

// One flipped byte of the bundled dragon that Draco decodes without complaint to another mesh
// (the volume goes from 155.7 to 432.7): with the original's sidecar beside it, it is refused.
TEST(Sidecar, CatchesADracoFlipThatDecodesToAnotherMesh) {
  ScratchDir dir("sidecar_draco");
  const std::string original = readBytes(dataFile("dragon.drc"));
  std::string flipped = original;
  flipped[flipped.size() - 3] = char(flipped[flipped.size() - 3] ^ 0xff);
  writeBytes(dir / "dragon.drc", flipped);
  const MeshReport changed = validateMesh(loadMesh(dir / "dragon.drc"));
  ASSERT_TRUE(changed.volume.has_value());
  EXPECT_GT(std::abs(*changed.volume - 155.7), 1.0);  // decodes, to a different dragon
  writeBytes(dir / "dragon.drc.sha256", sha256Hex(original) + "  dragon.drc\n");
  expectRefused(dir / "dragon.drc", dir / "dragon.drc", "does not match its .sha256 sidecar");
}

TEST(Sidecar, UppercaseHashAndBinaryMarkerAreAccepted) {
  ScratchDir dir("sidecar_forms");
  saveMesh(unitCube(), dir / "cube.ply");
  std::string hash = sha256Hex(readBytes(dir / "cube.ply"));
  for (char& c : hash) c = char(std::toupper(static_cast<unsigned char>(c)));
  writeBytes(dir / "cube.ply.sha256", hash + " *cube.ply\n");
  EXPECT_EQ(loadMesh(dir / "cube.ply").numTriangles(), 12u);
}

TEST(Sidecar, MalformedSidecarIsAnErrorNamingIt) {
  ScratchDir dir("sidecar_malformed");
  saveMesh(unitCube(), dir / "cube.obj");
  for (const std::string& text :
       {std::string("not a hash\n"), std::string(""), std::string(64, 'g') + "  cube.obj\n",
        std::string(64, 'a') + "cube.obj\n", std::string(5000, 'a')}) {
    writeBytes(dir / "cube.obj.sha256", text);
    expectRefused(dir / "cube.obj", dir / "cube.obj.sha256", "not a sha256sum line");
  }
}

TEST(Sidecar, FifoOrDeviceSidecarIsRefusedWithoutBlocking) {
  ScratchDir dir("sidecar_fifo");
  saveMesh(unitCube(), dir / "cube.off");
  fs::remove(dir / "cube.off.sha256");
  ASSERT_EQ(::mkfifo((dir / "cube.off.sha256").c_str(), 0600), 0);
  expectRefused(dir / "cube.off", dir / "cube.off.sha256", "not a regular file");
  fs::remove(dir / "cube.off.sha256");
  fs::create_symlink("/dev/zero", dir / "cube.off.sha256");
  expectRefused(dir / "cube.off", dir / "cube.off.sha256", "not a regular file");
}

TEST(Sidecar, OverwritingAMeshReplacesItsSidecar) {
  ScratchDir dir("sidecar_overwrite");
  saveMesh(unitCube(), dir / "m.ply");
  saveMesh(loadMesh(dataFile("bunny.off")), dir / "m.ply");
  EXPECT_EQ(loadMesh(dir / "m.ply").numTriangles(), 6966u);  // the new sidecar matches
}

}  // namespace
}  // namespace proxyvis::test
