#include "core/file_access.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace fxview {

namespace fs = std::filesystem;

namespace {

// The path with every symbolic link and `..` resolved, as far as it exists; empty on error
// (too long, unreadable), which no policy allows.
fs::path resolved(const fs::path& path) {
    std::error_code error;
    fs::path result = fs::weakly_canonical(fs::absolute(path, error), error);
    return error ? fs::path() : result;
}

bool is_inside(const fs::path& file, const fs::path& folder) {
    const auto mismatch = std::mismatch(folder.begin(), folder.end(), file.begin(), file.end());
    return mismatch.first == folder.end();
}

}  // namespace

void FileAccessPolicy::allow_folder(const fs::path& folder) {
    const fs::path canonical = resolved(folder);
    if (!canonical.empty() && std::find(folders_.begin(), folders_.end(), canonical) == folders_.end())
        folders_.push_back(canonical);
}

void FileAccessPolicy::allow_file(const fs::path& file) {
    const fs::path canonical = resolved(file);
    if (!canonical.empty()) files_.push_back(canonical);
}

bool FileAccessPolicy::allows(const fs::path& path) const {
    const fs::path canonical = resolved(path);
    if (canonical.empty()) return false;
    if (std::find(files_.begin(), files_.end(), canonical) != files_.end()) return true;
    return std::any_of(folders_.begin(), folders_.end(), [&](const fs::path& folder) { return is_inside(canonical, folder); });
}

void FileAccessPolicy::require(const fs::path& path, const std::string& what) const {
    if (allows(path)) return;
    std::string folders;
    for (const auto& folder : folders_) folders += (folders.empty() ? "" : ", ") + folder.string();
    throw Error(what + " '" + path.string() + "' is refused by the file-access policy: an effect may read only below " +
                (folders.empty() ? std::string("its own folder") : folders) + " (add a folder with --allow-path DIR)");
}

}  // namespace fxview
