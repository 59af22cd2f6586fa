#pragma once
// Where an output really goes, and the checks every program makes on its outputs right after
// parsing its flags, before any work: an output must not be one of the inputs (under any
// spelling: symbolic links, relative paths, hard links), two outputs must not be the same file,
// and the output's folder must exist or be creatable and be writable.
#include <filesystem>
#include <string>
#include <vector>

namespace proxyvis {

// What a path named as an output is, after following its symbolic links.
struct OutputTarget {
  enum class Kind {
    kFile,    // a regular file or nothing yet: written to a temporary beside it and renamed
    kStream,  // an open descriptor of this process (-, /dev/stdout, /dev/fd/N): written to it
    kDevice,  // an existing character device, FIFO or socket: opened and written in place
  };
  Kind kind = Kind::kFile;
  std::filesystem::path path;  // kFile: the final target (links resolved); kDevice: the node
  int fd = -1;                 // kStream
};

// Resolves `path` ("-" is stdout). Throws WriteError (exit 3) for a folder, a loop of symbolic
// links or a standard stream that is not open.
OutputTarget resolveOutputTarget(const std::filesystem::path& path);

// Creates `dir` and its missing parents; throws WriteError naming `output` (exit 3) with the
// system's reason if that fails.
void createOutputFolder(const std::filesystem::path& dir, const std::string& output);

// One output named on the command line.
struct OutputFlag {
  std::string flag;        // "--json", "-o", ... (for the message)
  std::string path;        // empty = not given; "-" = stdout
  bool is_folder = false;  // a folder the program fills (render-compare --out)
};

// The checks above. Inputs are the files named on the command line (missing ones are skipped:
// their loader reports them). Throws Error (exit 2) when an output is an input, contains an
// input (a folder output) or is named twice; WriteError (exit 3) when it cannot be written: its
// folder is a file, not writable or on a read-only file system, or the output is a folder.
// Missing parent folders are not created here (a run that fails later leaves nothing behind);
// the program's OutputSet (MissingFolders::kCreate) creates them when it writes.
void checkOutputs(const std::vector<std::string>& inputs, const std::vector<OutputFlag>& outputs);

}  // namespace proxyvis
