#include "ui/file_browser.hpp"

#include <imgui.h>

#include <algorithm>

namespace fxview::ui {

namespace fs = std::filesystem;

FolderListing list_folder(const fs::path& folder, const std::vector<std::string>& extensions) {
    FolderListing out;
    std::error_code error;
    for (auto it = fs::directory_iterator(folder, error); !error && it != fs::directory_iterator(); it.increment(error)) {
        const fs::path& path = it->path();
        if (path.filename().string().starts_with(".")) continue;
        std::error_code kind;
        if (it->is_directory(kind)) out.folders.push_back(path);
        else if (std::find(extensions.begin(), extensions.end(), path.extension().string()) != extensions.end()) out.files.push_back(path);
    }
    std::sort(out.folders.begin(), out.folders.end());
    std::sort(out.files.begin(), out.files.end());
    return out;
}

std::optional<std::string> FileBrowser::draw() {
    if (!listed_) {
        listing_ = list_folder(folder_, extensions_);
        listed_ = true;
    }
    std::optional<std::string> chosen;
    ImGui::TextUnformatted(folder_.string().c_str());
    ImGui::InputText("path", typed_, sizeof typed_);
    ImGui::SameLine();
    if (ImGui::Button("Open path") && typed_[0]) {
        std::error_code error;
        if (fs::is_directory(typed_, error)) set_folder(fs::absolute(typed_));
        else chosen = typed_;
    }
    ImGui::Separator();
    ImGui::BeginChild("entries", ImVec2(ImGui::GetFontSize() * 28, ImGui::GetFontSize() * 20));
    fs::path next;
    if (folder_.has_parent_path() && folder_.parent_path() != folder_ && ImGui::Selectable("../", false, ImGuiSelectableFlags_DontClosePopups))
        next = folder_.parent_path();
    for (const auto& sub : listing_.folders)
        if (ImGui::Selectable((sub.filename().string() + "/").c_str(), false, ImGuiSelectableFlags_DontClosePopups)) next = sub;
    for (const auto& file : listing_.files)
        if (ImGui::Selectable(file.filename().string().c_str())) chosen = file.string();
    if (listing_.folders.empty() && listing_.files.empty()) ImGui::TextDisabled("(no effect files here)");
    ImGui::EndChild();
    if (!next.empty()) set_folder(next);
    return chosen;
}

}  // namespace fxview::ui
