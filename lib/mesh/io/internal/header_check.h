#pragma once
// Checks a file before OpenMesh's reader sees it. Element counts a PLY or OFF header declares are
// checked against the file size: a header that claims 2^31 vertices in a 1 KB file is an Error,
// not an 8 GB allocation (OpenMesh reserves what the header says). And the syntax OpenMesh cannot
// survive is rejected first: in fuzzing its readers looped forever on corrupt PLY headers and
// non-numeric ASCII tokens, and its OBJ reader aborted on face corners like "/0".
#include <string>

namespace proxyvis::detail {

// Throws Error naming `file` when the header of `bytes` (the whole file) is unreadable or declares
// more elements than the file could hold, or malformed syntax. `ext` is "ply", "off" or "obj".
void checkDeclaredCounts(const std::string& bytes, const std::string& ext, const std::string& file);

// The checks by format, one walk over the file each (ply_check.cpp, off_check.cpp, obj_check.cpp).
void checkPly(const std::string& bytes, const std::string& file);
void checkOff(const std::string& bytes, const std::string& file);  // ASCII only: binary is refused
void checkObj(const std::string& bytes, const std::string& file);

// Replaces '#' comments of an ASCII OFF file by spaces (line numbers stay). OFF allows comments
// anywhere, OpenMesh's reader skips them only in the header: in the body "#" failed its stream
// and it went on with uninitialised values. For a file checkOff accepted (it refuses binary OFF).
void blankOffComments(std::string& bytes);

}  // namespace proxyvis::detail
