// The effect the viewer shows: opening it (technique, --set values, preset), watching its files, also
// after a failed start, reloading while the last good effect and the user's values stay, widening
// what it may read; the message of the last failure (`file:line` places, error_list.hpp).
#pragma once
#include <chrono>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "app/effect_options.hpp"
#include "render/effect_session.hpp"
#include "ui/error_list.hpp"

namespace fxview::ui {

class EffectState {
public:
    explicit EffectState(app::AccessOptions access) : access_(std::move(access)) {}

    // Opens `path` (the request is kept: a failed one is retried when the file changes). True when it
    // opened; on failure the last good effect stays and error() says why.
    bool open(const std::string& path, const std::string& technique = "", const std::vector<std::string>& sets = {},
              const std::string& preset = "");
    // The last request again (the Reload button of an effect that failed at start).
    bool retry() { return open(request_.path, request_.technique, request_.sets, request_.preset); }
    // Called every frame; twice a second it reloads when a watched file changed, or retries a failed
    // start whose file was written. True when a new effect was opened by a retry.
    bool poll();
    void reload();  // the Reload button: the same effect, the user's values kept
    // Lets effects read below `folder` too (the viewer's --allow-path) and loads again with it.
    // UsageError for a missing folder.
    void allow_folder(const std::string& folder);
    std::vector<std::string> allowed_folders() const;

    render::EffectSession* session() { return session_.get(); }
    const render::EffectSession* session() const { return session_.get(); }
    const std::string& path() const { return path_; }                    // the effect shown ("" for none)
    const std::string& requested_path() const { return request_.path; }  // the last one asked for
    const std::string& error() const { return error_; }
    // The error's file:line places, found when the error is set (they stat files: not every frame).
    const std::vector<ErrorLocation>& error_places() const { return error_places_; }
    void set_error(std::string message) {
        error_ = std::move(message);
        error_places_ = error_locations(error_);
    }

private:
    struct Request {
        std::string path, technique;
        std::vector<std::string> sets;
        std::string preset;
    };
    bool request_file_changed();

    app::AccessOptions access_;
    std::unique_ptr<render::EffectSession> session_;
    std::string path_, error_;
    std::vector<ErrorLocation> error_places_;
    Request request_;
    std::filesystem::file_time_type request_time_{};  // the requested file's time at the last attempt
    std::chrono::steady_clock::time_point last_poll_ = std::chrono::steady_clock::now();
};

}  // namespace fxview::ui
