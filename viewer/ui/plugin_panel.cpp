#include "ui/plugin_panel.hpp"

#include <glad/gl.h>
#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>

#include "app/effect_options.hpp"
#include "image/color_encoding.hpp"

namespace fxview::ui {
namespace {

const ImVec4 kRed(1.0f, 0.4f, 0.3f, 1.0f), kGreen(0.5f, 0.9f, 0.5f, 1.0f), kAmber(1.0f, 0.75f, 0.3f, 1.0f);

// One stage's cost curve on a log axis with its decades labelled: costs fall over orders of magnitude.
void draw_cost_curve(const std::string& stage, const std::vector<double>& costs) {
    std::vector<float> curve;
    for (const double c : costs)
        if (c > 0 && std::isfinite(c)) curve.push_back(static_cast<float>(std::log10(c)));
    if (curve.size() < 2) return;
    const auto [low, high] = std::minmax_element(curve.begin(), curve.end());
    const float bottom = std::floor(*low), top = std::max(std::ceil(*high), bottom + 1.0f);
    ImGui::Text("%s%scost (log scale): 1e%+.0f at the top, 1e%+.0f at the bottom; %zu reports", stage.c_str(),
                stage.empty() ? "" : ": ", top, bottom, curve.size());
    char overlay[64];
    std::snprintf(overlay, sizeof overlay, "last %.4g", std::pow(10.0, curve.back()));
    ImGui::PlotLines(("##cost" + stage).c_str(), curve.data(), static_cast<int>(curve.size()), 0, overlay, bottom, top,
                     ImVec2(ImGui::GetContentRegionAvail().x, 70));
}

}  // namespace

PluginPanel::~PluginPanel() {
    if (run_) run_->cancel = true;
    if (worker_.joinable()) worker_.join();
}

bool PluginPanel::start(render::EffectSession* session, const std::string& name, const std::string& user_file) {
    error_.clear();
    if (running()) {
        error_ = "a plugin is running: cancel it first";
        return false;
    }
    if (worker_.joinable()) worker_.join();
    if (!session) {
        error_ = "no effect loaded";
        return false;
    }
    const effect::Effect& effect = session->effect();
    const effect::PluginDeclaration* declaration = nullptr;
    for (const auto& d : effect.plugins)
        if (name.empty() || d.name == name) {
            declaration = &d;
            break;
        }
    if (!declaration) {
        error_ = effect.plugins.empty() ? "the effect declares no plugin" : "the effect has no plugin '" + name + "'";
        return false;
    }
    std::shared_ptr<plugin::Plugin> plugin;
    try {
        plugin = plugin::create(effect, *declaration, app::texture_folders());  // the run's own copy: reloads cannot pull it away
    } catch (const std::exception& e) {
        error_ = e.what();
        return false;
    }
    last_plugin_ = plugin->name();
    before_ = session->values();
    technique_before_ = session->technique();
    technique_change_.clear();
    switched_technique_ = false;
    // The live parameters are seen with the technique that reads them.
    if (const std::string t = plugin->technique(); !t.empty() && t != technique_before_ && effect.find_technique(t)) {
        session->select_technique(t);
        technique_change_ = t;
        switched_technique_ = true;
    }
    result_.reset();
    curves_.clear();
    run_ = std::make_shared<PluginRun>();
    worker_ = std::thread([run = run_, plugin, values = session->values(), user_file] {
        const plugin::Reporter reporter(
            [&run](const plugin::Progress& p) {
                const std::lock_guard lock(run->mutex);
                run->progress = p;
                run->fresh = true;
                if (!(p.cost > 0)) return;
                if (run->curves.empty() || run->curves.back().first != p.stage) run->curves.push_back({p.stage, {}});
                run->curves.back().second.push_back(p.cost);
            },
            &run->cancel);
        std::optional<plugin::Result> result;
        std::string error;
        try {
            result = plugin->run(values, reporter, user_file);
        } catch (const plugin::Cancelled&) {
            error = "cancelled: the parameters are as they were before the run";
        } catch (const std::exception& e) {
            error = e.what();
        }
        const std::lock_guard lock(run->mutex);
        run->result = std::move(result);
        run->error = std::move(error);
        run->done = true;
    });
    return true;
}

void PluginPanel::wait(render::EffectSession* session) {
    if (worker_.joinable()) worker_.join();
    update(session);
}

void PluginPanel::update(render::EffectSession* session) {
    if (session && &session->effect() != effect_) {  // a new or reloaded effect: its own plugins
        effect_ = &session->effect();
        plugins_.clear();
        plugins_error_.clear();
        try {
            plugins_ = plugin::create_all(session->effect(), app::texture_folders());
        } catch (const std::exception& e) {
            plugins_error_ = e.what();
        }
        selected_ = std::clamp(selected_, 0, std::max(0, static_cast<int>(plugins_.size()) - 1));
    }
    if (!run_) return;
    std::optional<plugin::Progress> progress;
    bool done = false;
    {
        const std::lock_guard lock(run_->mutex);
        if (run_->fresh) progress = run_->progress;
        run_->fresh = false;
        curves_ = run_->curves;
        done = run_->done;
    }
    if (progress && session && !done) {  // live: the picture follows the solver
        plugin::Result live;
        live.parameters = progress->parameters;
        plugin::apply(session->effect(), session->values(), live);
    }
    if (done) finish(session);
}

void PluginPanel::finish(render::EffectSession* session) {
    if (worker_.joinable()) worker_.join();
    std::optional<plugin::Result> result;
    {
        const std::lock_guard lock(run_->mutex);
        result = std::move(run_->result);
        error_ = run_->error;
    }
    run_.reset();
    if (!result) {
        if (session) {  // the live updates are undone: a failed run changes nothing
            for (auto& [name, value] : session->values().numbers)
                if (const auto b = before_.numbers.find(name); b != before_.numbers.end() && b->second.size() == value.size()) value = b->second;
            if (switched_technique_ && session->effect().find_technique(technique_before_)) {
                session->select_technique(technique_before_);
                technique_change_ = technique_before_;
            }
        }
        return;
    }
    if (session) {
        const std::vector<std::string> missing = plugin::apply(session->effect(), session->values(), *result);
        for (const auto& reason : missing) result->warnings.push_back("not written: " + reason);
        if (!result->technique.empty() && session->effect().find_technique(result->technique)) {
            session->select_technique(result->technique);
            technique_change_ = result->technique;
        }
    }
    size_t reports = 0;
    for (const auto& [stage, costs] : curves_) reports += costs.size();
    if (reports < 2) curves_ = {{"", result->cost_per_iteration}};  // the live reports, else the plugin's own history
    if (result->preview) preview_ = upload_ui_image(*result->preview, true);
    result_ = std::move(result);
}

void PluginPanel::draw(render::EffectSession* session) {
    ImGui::PushTextWrapPos(0.0f);
    if (!plugins_error_.empty()) ImGui::TextColored(kRed, "%s", plugins_error_.c_str());
    if (plugins_.empty()) {
        ImGui::TextWrapped("This effect declares no plugin. Effects run built-in plugins, such as the BRDF fit of "
                           "effects/brdf/measured.fx and effects/brdf/analytic.fx, from a 'plugin' block (docs/plugins.md).");
        ImGui::PopTextWrapPos();
        return;
    }
    for (int i = 0; i < static_cast<int>(plugins_.size()); ++i) {
        const plugin::Plugin& p = *plugins_[static_cast<size_t>(i)];
        if (ImGui::RadioButton((p.name() + " (" + p.type() + ")").c_str(), selected_ == i)) selected_ = i;
    }
    const plugin::Plugin& plugin = *plugins_[static_cast<size_t>(selected_)];
    ImGui::TextDisabled("%s", plugin.description().c_str());
    std::string writes;
    for (const auto& s : plugin.outputs()) writes += (writes.empty() ? "" : ", ") + s;
    ImGui::TextDisabled("writes %s", writes.c_str());
    ImGui::InputTextWithHint("Data file", "(the effect's own data)", data_file_, sizeof data_file_);
    if (running()) {
        float fraction = 0;
        std::string stage;
        {
            const std::lock_guard lock(run_->mutex);
            if (run_->progress) {
                fraction = static_cast<float>(run_->progress->fraction);
                stage = run_->progress->stage;
            }
        }
        ImGui::ProgressBar(fraction, ImVec2(-1, 0), stage.c_str());
        if (ImGui::Button("Cancel")) run_->cancel = true;
    } else if (ImGui::Button("Run")) {
        start(session, plugin.name(), data_file_);
    }
    if (!error_.empty()) ImGui::TextColored(kRed, "%s", error_.c_str());
    for (const auto& [stage, costs] : curves_) draw_cost_curve(stage, costs);
    if (result_ && !running()) {
        ImGui::Separator();
        ImGui::Text("%s", last_plugin_.c_str());
        if (result_->converged) ImGui::TextColored(kGreen, "Converged");
        else ImGui::TextColored(kRed, "NOT converged");
        for (const auto& line : result_->summary) ImGui::TextWrapped("%s", line.c_str());
        for (const auto& warning : result_->warnings) ImGui::TextColored(kAmber, "%s", warning.c_str());
        if (!preview_.empty()) {
            ImGui::TextDisabled("%s", result_->preview_caption.c_str());
            preview_.draw();
        }
    }
    ImGui::PopTextWrapPos();
}

}  // namespace fxview::ui
