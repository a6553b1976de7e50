// Which files an effect may read. Effect files travel between people like documents, so by
// default an effect reads includes, textures and data only below its own folder and the project's
// search roots (effects/lib, textures/, spectra/); `--allow-path DIR` (and the viewer's Security
// setting) adds folders. Paths are compared after resolving symbolic links and `..`, so a link
// that points outside the allowed folders is refused like any other outside path.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace fxview {

class FileAccessPolicy {
public:
    FileAccessPolicy() = default;
    // Adds a folder whose files (at any depth) may be read.
    void allow_folder(const std::filesystem::path& folder);
    // Adds one file, e.g. named by the user on the command line.
    void allow_file(const std::filesystem::path& file);
    // Whether `path` resolves (symbolic links followed) to a file inside an allowed folder.
    bool allows(const std::filesystem::path& path) const;
    // Throws Error "`path` is outside the folders this effect may read (...)" unless allowed. The
    // message names the policy and the allowed folders, never anything read from the file.
    void require(const std::filesystem::path& path, const std::string& what) const;
    const std::vector<std::filesystem::path>& folders() const { return folders_; }

private:
    std::vector<std::filesystem::path> folders_;  // canonical
    std::vector<std::filesystem::path> files_;    // canonical
};

}  // namespace fxview
