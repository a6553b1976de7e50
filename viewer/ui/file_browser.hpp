// The Open dialog's folder browser: one folder at a time (its subfolders, then its effect files),
// a parent entry, and a typed path; it starts at the effects folder and lists only effect files.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace fxview::ui {

struct FolderListing {
    std::vector<std::filesystem::path> folders, files;  // sorted by name
};

// The subfolders (hidden ones left out) and the files with one of `extensions` in `folder`.
FolderListing list_folder(const std::filesystem::path& folder, const std::vector<std::string>& extensions);

class FileBrowser {
public:
    explicit FileBrowser(std::filesystem::path start, std::vector<std::string> extensions = {".fx", ".brdf"})
        : folder_(std::move(start)), extensions_(std::move(extensions)) {}

    // Draws the browser inside the current popup; returns the file chosen this frame.
    std::optional<std::string> draw();
    const std::filesystem::path& folder() const { return folder_; }
    void set_folder(const std::filesystem::path& folder) { folder_ = folder, listed_ = false; }

private:
    std::filesystem::path folder_;
    std::vector<std::string> extensions_;
    FolderListing listing_;
    bool listed_ = false;
    char typed_[512] = "";
};

}  // namespace fxview::ui
