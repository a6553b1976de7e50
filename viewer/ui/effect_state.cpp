#include "ui/effect_state.hpp"

namespace fxview::ui {

bool EffectState::open(const std::string& path, const std::string& technique, const std::vector<std::string>& sets,
                       const std::string& preset) {
    request_ = {path, technique, sets, preset};
    std::error_code time_error;
    request_time_ = std::filesystem::last_write_time(path, time_error);  // the version this attempt reads
    try {
        app::EffectOptions options;
        options.access = access_;
        options.path = path;
        options.technique = technique;
        options.sets = sets;
        options.preset = preset;
        session_ = app::open_effect_session(options);
        path_ = path;
        set_error("");
        return true;
    } catch (const std::exception& error) {
        set_error(error.what());  // the last good effect (if any) stays
        return false;
    }
}

bool EffectState::request_file_changed() {
    if (request_.path.empty()) return false;
    std::error_code error;
    const auto written = std::filesystem::last_write_time(request_.path, error);
    if (error || written == request_time_) return false;
    request_time_ = written;
    return true;
}

bool EffectState::poll() {
    const auto now = std::chrono::steady_clock::now();
    if (now - last_poll_ < std::chrono::milliseconds(500)) return false;
    last_poll_ = now;
    if (session_ && session_->files_changed()) {
        reload();
        return false;
    }
    // An effect that failed at start is watched too: saving the fix opens it.
    return !session_ && request_file_changed() && retry();
}

void EffectState::reload() {
    const auto error = session_->reload();
    set_error(error ? *error : std::string());
}

void EffectState::allow_folder(const std::string& folder) {
    app::AccessOptions widened = access_;
    widened.allow_paths.push_back(folder);
    effect::LoadOptions load_options = app::effect_load_options(widened);  // UsageError for a missing folder
    access_ = std::move(widened);
    if (session_) {
        session_->set_load_options(std::move(load_options));
        reload();  // a running effect keeps the user's values
    } else if (!request_.path.empty()) {
        retry();  // one refused at start opens now
    }
}

std::vector<std::string> EffectState::allowed_folders() const {
    std::vector<std::string> folders;
    for (const auto& folder : app::effect_load_options(access_).access.folders()) folders.push_back(folder.string());
    return folders;
}

}  // namespace fxview::ui
