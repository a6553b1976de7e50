// The Plugins tab (docs/plugins.md): the plugins the current effect declares, each run on a worker
// thread so that the viewer stays responsive, with a progress bar, a Cancel button, the parameters
// and picture updated live as the plugin reports, the cost per iteration on a log axis, and the
// plugin's preview image. A failed or cancelled run leaves the parameters as they were before it.
#pragma once
#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "gl/objects.hpp"
#include "plugin/plugin.hpp"
#include "render/effect_session.hpp"
#include "ui/ui_image.hpp"

namespace fxview::ui {

// The cost per report, one curve per stage: stages may fit different data (the BRDF fit's search
// runs on a subset, its polish on all samples), so their costs do not share an axis.
using CostCurves = std::vector<std::pair<std::string, std::vector<double>>>;

// What the worker thread and the UI thread share; guarded by `mutex` apart from `cancel`.
struct PluginRun {
    std::mutex mutex;
    std::optional<plugin::Progress> progress;  // the latest report
    bool fresh = false;                        // a report the UI has not applied yet
    CostCurves curves;
    std::optional<plugin::Result> result;
    std::string error;
    bool done = false;
    std::atomic<bool> cancel{false};
};

class PluginPanel {
public:
    PluginPanel() = default;
    PluginPanel(const PluginPanel&) = delete;
    PluginPanel& operator=(const PluginPanel&) = delete;
    ~PluginPanel();  // cancels and joins a running plugin

    // Once a frame: rebuilds the list after a reload, applies live progress and a finished result
    // to the session's parameters.
    void update(render::EffectSession* session);
    void draw(render::EffectSession* session);
    // Starts the named plugin (the first when empty) on a worker thread; `user_file` replaces its
    // data file. Returns false with error() set when it cannot start.
    bool start(render::EffectSession* session, const std::string& name, const std::string& user_file = {});
    // Blocks until the running plugin has finished and applies its result (scripts, tests).
    void wait(render::EffectSession* session);
    bool running() const { return run_ && worker_.joinable(); }
    const std::optional<plugin::Result>& result() const { return result_; }
    const std::string& error() const { return error_; }
    const std::string& last_plugin() const { return last_plugin_; }
    // The technique the objects should switch to, once: the plugin's while it runs and after it
    // succeeded, the one before it after a failure or Cancel. Empty when nothing changed.
    std::string take_technique_change() { return std::exchange(technique_change_, {}); }

private:
    void finish(render::EffectSession* session);

    const effect::Effect* effect_ = nullptr;  // what `plugins_` were made for
    std::vector<std::unique_ptr<plugin::Plugin>> plugins_;
    std::string plugins_error_;
    int selected_ = 0;
    char data_file_[512] = "";
    std::shared_ptr<PluginRun> run_;
    std::thread worker_;
    effect::ParameterValues before_;  // restored when a run fails or is cancelled
    std::string technique_before_, technique_change_;
    bool switched_technique_ = false;  // start() selected the plugin's technique
    std::string last_plugin_, error_;
    std::optional<plugin::Result> result_;
    CostCurves curves_;
    UiImage preview_;
};

}  // namespace fxview::ui
