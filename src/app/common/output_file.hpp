#pragma once
// Writing a command's output file safely: never over one of its inputs (the same file by
// identity, device and inode, so a hard link, a symbolic link or another spelling of the path is
// caught too), never over an existing file unless asked, and atomically (a temporary file in the
// same folder, flushed to disk, then renamed over the target: a reader never sees half a file
// and a failure leaves any earlier file as it was).

#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace trailray::app {

// Throws std::runtime_error naming `output` when it is one of `inputs` ("-" never is), when it is
// an existing file and `force` is false, or when it is a folder. A device or a named pipe
// (/dev/null, /dev/stdout) may be written without --force.
void check_output_path(const std::string& output, const std::vector<std::string>& inputs, bool force);

// Calls `write` with a stream into a temporary file next to `output`, then renames it over
// `output` (a device or a named pipe is written directly). Throws std::runtime_error naming `output` and the reason;
// the temporary file is removed on any failure, also when `write` throws.
void write_file_atomically(const std::string& output, const std::function<void(std::ostream&)>& write);

// For writers that open the file themselves (a video encoder): a free name in `output`'s folder,
// and the flush to disk and rename that put such a file in place (throws std::runtime_error
// naming `output`; the temporary file is then removed).
std::string temporary_path_next_to(const std::string& output);
void replace_with_temporary(const std::string& temporary, const std::string& output);

}  // namespace trailray::app
