#include "ui/scene_panel.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "math/arcball.hpp"
#include "math/transform.hpp"
#include "render/effect_session.hpp"
#include "scene/shapes.hpp"
#include "ui/light_marker.hpp"
#include "ui/scene_layout.hpp"

namespace fxview::ui {

ViewMode parse_view(const std::string& name) {
    for (int i = 0; i < 6; ++i)
        if (name == kViewNames[i]) return static_cast<ViewMode>(i);
    throw UsageError("unknown view '" + name + "' (effect, plain, normals, uv, camera, light)");
}

render::DebugView debug_view(ViewMode mode) {
    switch (mode) {
        case ViewMode::Normals: return render::DebugView::Normals;
        case ViewMode::TexCoords: return render::DebugView::TexCoords;
        case ViewMode::ToCamera: return render::DebugView::ToCamera;
        case ViewMode::ToLight: return render::DebugView::ToLight;
        default: return render::DebugView::Plain;
    }
}

void ViewerScene::move_selected(const glm::vec3& view_move) {
    const glm::vec3 world_move = glm::inverse(glm::mat3_cast(scene.camera.pose.rotation)) * view_move;
    if (selected == Target::Camera) scene.camera.pose.pan -= glm::vec2(view_move);
    else if (selected == Target::Light) scene.light.pose.position += glm::vec3(glm::mat3_cast(glm::inverse(scene.light.pose.rotation)) * world_move);
    else if (!objects.empty()) {
        auto& moved = objects[static_cast<size_t>(selected_object)];
        for (auto& o : objects)
            if (&o == &moved || (moved.grouped && o.grouped)) o.object.pose.position += world_move;
    }
}

void ViewerScene::rotate_selected(const glm::quat& view_rotation) {
    if (selected == Target::Camera) {
        scene.camera.pose.rotation = glm::normalize(view_rotation * scene.camera.pose.rotation);
    } else if (selected == Target::Light) {
        scene.light.pose.rotation = math::rotate_in_view(scene.light.pose.rotation, view_rotation, scene.camera.pose.rotation);
    } else if (!objects.empty()) {
        auto& selected = objects[static_cast<size_t>(selected_object)];
        const bool group = selected.grouped;
        for (auto& o : objects)
            if (&o == &selected || (group && o.grouped))
                o.object.pose.rotation = math::rotate_in_view(o.object.pose.rotation, view_rotation, scene.camera.pose.rotation);
    }
}

void ViewerScene::reset_selected() {
    if (selected == Target::Camera) scene.camera = initial.camera;
    else if (selected == Target::Light) scene.light = initial.light;
    else if (!objects.empty()) {
        auto& o = objects[static_cast<size_t>(selected_object)].object;
        o.pose = {};
        o.scale = glm::vec3(1.0f);
    }
}

void ViewerScene::reset_all() {
    scene.camera = initial.camera;
    scene.light = initial.light;
    for (auto& o : objects) o.object.pose = {}, o.object.scale = glm::vec3(1.0f);
}

glm::vec3 ViewerScene::beside_the_others(const glm::vec3& scale) const {
    std::vector<scene::SceneObject> placed;
    for (const auto& o : objects) placed.push_back(o.object);
    return place_beside(placed, scale);
}

void ViewerScene::add_to(StateHash& h) const {
    // Field by field: the structs hold floats only, but hashing members keeps padding out.
    const auto& c = scene.camera;
    h.add(c.pose.rotation.w).add(c.pose.rotation.x).add(c.pose.rotation.y).add(c.pose.rotation.z).add(c.pose.pan.x).add(c.pose.pan.y);
    h.add(c.pose.distance).add(c.fov_y_degrees).add(c.near_plane).add(c.far_plane);
    const glm::vec3 light = scene.light.world_position();
    h.add(light.x).add(light.y).add(light.z).add(scene.light.radius);
    h.add(scene.light.intensity ? scene.light.intensity->value : -1.0).add(scene.light.intensity ? static_cast<int>(scene.light.intensity->unit) : -1);
    h.add(static_cast<int>(scene.light.shape)).add(scene.light.size.x).add(scene.light.size.y);
    h.add(scene.light.spectrum);
    h.add(scene.background.r).add(scene.background.g).add(scene.background.b).add(scene.background.a);
    h.add(scene.environment.source).add(scene.environment.rotation_degrees).add(scene.environment.intensity);
    for (const auto& o : objects) {
        const auto& p = o.object.pose;
        h.add(o.object.mesh).add(p.position.x).add(p.position.y).add(p.position.z);
        h.add(p.rotation.w).add(p.rotation.x).add(p.rotation.y).add(p.rotation.z);
        h.add(o.object.scale.x).add(o.object.scale.y).add(o.object.scale.z).add(o.technique).add(static_cast<int>(o.view));
    }
}

void draw_light_spectrum(scene::Light& light, const render::EffectSession* session) {
    const effect::Parameter* follower = nullptr;
    if (session)
        for (const effect::Parameter& p : session->effect().parameters)
            if (render::EffectSession::follows_scene_light(p)) follower = &p;
    if (!follower) {
        if (!light.spectrum.empty()) {
            ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.3f, 1.0f), "No parameter of this effect takes the light's spectrum (%s).", light.spectrum.c_str());
            if (ImGui::SmallButton("clear the light spectrum")) light.spectrum.clear();
        }
        return;
    }
    const char* own = "the effect's own";
    if (ImGui::BeginCombo("light spectrum", light.spectrum.empty() ? own : light.spectrum.c_str())) {
        if (ImGui::Selectable(own, light.spectrum.empty())) light.spectrum.clear();
        for (const std::string& name : follower->ui.items)
            if (ImGui::Selectable(name.c_str(), name == light.spectrum)) light.spectrum = name;
        ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("The light's spectrum in every spectral effect: it overrides the effect's '%s' while set", follower->ui.label.empty() ? follower->name.c_str() : follower->ui.label.c_str());
}

namespace {

// The light's shape and size: a sphere (a point at radius 0), a disc or a rectangle facing the origin.
void draw_light_shape(scene::Light& light, glm::vec3 position, const std::string& light_warning) {
    const char* shapes[] = {"sphere", "disc", "rectangle"};
    int shape = static_cast<int>(light.shape);
    if (ImGui::Combo("light shape", &shape, shapes, 3)) light.shape = static_cast<scene::LightShape>(shape);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("sphere: a lamp (a point at radius 0). disc, rectangle: a flat panel or window facing the origin, as bright "
                          "there as the point light; nearer surfaces get more of its light");
    const float distance = glm::length(position);
    if (light.shape == scene::LightShape::Rectangle) {
        ImGui::DragFloat2("light width, height", &light.size.x, 0.01f, 0.0f, 1e3f, "%.2f", ImGuiSliderFlags_AlwaysClamp);
    } else {
        ImGui::DragFloat("light radius", &light.radius, 0.01f, 0.0f, 1e3f, "%.2f", ImGuiSliderFlags_AlwaysClamp);
        if (ImGui::IsItemHovered()) {
            // Seen from the origin: a sphere subtends asin(R / D), a disc facing it atan(R / D).
            const float angle = light.shape == scene::LightShape::Sphere ? (distance > light.radius ? std::asin(light.radius / distance) : 1.5708f)
                                                                          : std::atan2(light.radius, distance);
            ImGui::SetTooltip("0: a point light. Larger: a lamp, a ceiling panel, a window (%.1f degrees angular radius seen from the origin). "
                              "Reflections and diffraction orders show its size; techniques that treat it as a point say so",
                              glm::degrees(angle));
        }
    }
    // The intensity in photometric units, or each effect's own light strength.
    bool photometric = light.intensity.has_value();
    if (ImGui::Checkbox("light intensity", &photometric)) light.intensity = photometric ? std::optional(scene::LightIntensity{500.0}) : std::nullopt;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Off: each effect's own light strength (Brightness, E). On: the light in lx, lm, cd or nit; the picture is then "
                          "luminance in cd/m2, so lower the exposure (View tab) to see it");
    if (light.intensity) {
        ImGui::SameLine();
        float value = static_cast<float>(light.intensity->value);
        ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6.0f);
        if (ImGui::DragFloat("##intensity", &value, std::max(value, 1.0f) * 0.01f, 0.0f, 1e9f, "%.1f", ImGuiSliderFlags_AlwaysClamp)) light.intensity->value = value;
        ImGui::SameLine();
        const char* units[] = {"lx", "lm", "cd", "nit"};
        int unit = static_cast<int>(light.intensity->unit);
        ImGui::SetNextItemWidth(ImGui::GetFontSize() * 4.0f);
        if (ImGui::Combo("##unit", &unit, units, 4)) light.intensity->unit = static_cast<scene::LightIntensity::Unit>(unit);
        try {
            scene::Light probe = light;
            probe.pose.position = position;  // the world position, as the renderer sees it
            probe.pose.rotation = glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
            const double lux = scene::illuminance_at_origin(probe, *light.intensity);
            // A white Lambertian surface facing it shows E / π cd/m²; the exposure that puts it at 0.8.
            ImGui::TextDisabled("%.1f lx at the origin: a white surface facing it shows %.1f cd/m2\n(exposure %.1f EV, View tab, shows it at 0.8)",
                                lux, lux / 3.14159265358979, lux > 0 ? std::log2(0.8 * 3.14159265358979 / lux) : 0.0);
        } catch (const std::exception& error) {
            ImGui::TextColored(ImVec4(1.0f, 0.75f, 0.3f, 1.0f), "%s", error.what());
        }
    }
    // Each warning (one per line) without its "file: warning:" head.
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.75f, 0.3f, 1.0f));
    size_t start = 0;
    while (start < light_warning.size()) {
        size_t end = light_warning.find('\n', start);
        if (end == std::string::npos) end = light_warning.size();
        const std::string line = light_warning.substr(start, end - start);
        const size_t head = line.find("warning: ");
        ImGui::TextWrapped("%s", head == std::string::npos ? line.c_str() : line.substr(head + 9).c_str());
        start = end + 1;
    }
    ImGui::PopStyleColor();
}

}  // namespace

void draw_scene_panel(ViewerScene& view, const std::string& technique, bool has_effect, const std::string& light_warning,
                      std::string& status) {
    ImGui::TextWrapped("Turn with the left mouse button, move with the right, zoom with the wheel.");
    const char* targets[] = {"Camera", "Light", "Object"};
    int selected = static_cast<int>(view.selected);
    if (ImGui::Combo("drag moves", &selected, targets, 3)) view.selected = static_cast<Target>(selected);
    ImGui::DragFloat("camera distance", &view.scene.camera.pose.distance, 0.02f, 0.1f, 100.0f);
    ImGui::DragFloat2("camera pan", &view.scene.camera.pose.pan.x, 0.01f);
    ImGui::SliderFloat("field of view", &view.scene.camera.fov_y_degrees, 5.0f, 120.0f);
    // The light's world position (drags orbit it: the field follows them, and editing it moves the light there).
    glm::vec3 light = view.scene.light.world_position();
    if (ImGui::DragFloat3("light position", &light.x, 0.05f))
        view.scene.light.pose.position = glm::inverse(glm::mat3_cast(view.scene.light.pose.rotation)) * light;
    draw_light_shape(view.scene.light, light, light_warning);
    ImGui::Checkbox("show the light in the view", &view.show_light);
    ImGui::ColorEdit4("background", &view.scene.background.r, ImGuiColorEditFlags_Float);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Linear RGBA the picture is cleared to; where alpha is 0 the view shows its grey backdrop");
    ImGui::Separator();
    if (ImGui::Button("Add")) {
        ObjectState added{scene::SceneObject{}, technique, has_effect ? ViewMode::Effect : ViewMode::Normals, false};
        added.object.pose.position = view.beside_the_others(added.object.scale);
        view.objects.push_back(added);
        view.selected_object = static_cast<int>(view.objects.size()) - 1;
    }
    ImGui::SameLine();
    if (ImGui::Button("Duplicate") && !view.objects.empty()) {
        ObjectState copy = view.objects[static_cast<size_t>(view.selected_object)];
        copy.object.pose.position = view.beside_the_others(copy.object.scale);
        view.objects.push_back(copy);
        view.selected_object = static_cast<int>(view.objects.size()) - 1;
    }
    ImGui::SameLine();
    if (ImGui::Button("Remove") && view.objects.size() > 1) {
        view.objects.erase(view.objects.begin() + view.selected_object);
        view.selected_object = std::min(view.selected_object, static_cast<int>(view.objects.size()) - 1);
    }
    for (int i = 0; i < static_cast<int>(view.objects.size()); ++i) {
        ImGui::PushID(i);
        ImGui::Checkbox("##group", &view.objects[static_cast<size_t>(i)].grouped);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("In the group: turned and moved together");
        ImGui::SameLine();
        const std::string label = std::to_string(i) + ": " + view.objects[static_cast<size_t>(i)].object.mesh;
        if (ImGui::Selectable(label.c_str(), i == view.selected_object)) {
            view.selected_object = i;
            view.selected = Target::Object;
        }
        ImGui::PopID();
    }
    if (view.objects.empty()) return;
    auto& o = view.objects[static_cast<size_t>(view.selected_object)];
    ImGui::Separator();
    if (ImGui::BeginCombo("mesh", o.object.mesh.c_str())) {
        for (const auto& name : scene::builtin_mesh_names())
            if (ImGui::Selectable(name.c_str(), name == o.object.mesh)) o.object.mesh = name;
        ImGui::EndCombo();
    }
    static char obj_file[512] = "model.obj";  // the field's text (one panel per process)
    ImGui::InputText("OBJ file", obj_file, sizeof obj_file);
    ImGui::SameLine();
    if (ImGui::Button("Use")) {
        try {
            scene::load_mesh(obj_file);  // check before the renderer meets it
            o.object.mesh = obj_file;
        } catch (const std::exception& e) {
            status = e.what();
        }
    }
    int mode = static_cast<int>(o.view);
    if (ImGui::Combo("view", &mode, kViewNames, 6)) o.view = static_cast<ViewMode>(mode);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("effect, plain rendering (no effect) or a debug view");
    ImGui::DragFloat3("position", &o.object.pose.position.x, 0.01f);
    glm::vec3 euler = glm::degrees(glm::eulerAngles(o.object.pose.rotation));
    if (ImGui::DragFloat3("rotation", &euler.x, 0.5f)) o.object.pose.rotation = glm::quat(glm::radians(euler));
    ImGui::DragFloat3("scale", &o.object.scale.x, 0.01f, 0.01f, 100.0f);
}

void draw_light_gizmo(const ViewerScene& view, ImDrawList* list, ImVec2 origin, ImVec2 shown) {
    if (!view.show_light || shown.x <= 0 || shown.y <= 0) return;
    const float r = ImGui::GetFontSize() * 0.45f;
    const LightMarker marker = light_marker(view.scene.camera, view.scene.light.world_position(), {shown.x, shown.y}, r * 3.0f);
    const ImVec2 at(origin.x + marker.at.x, origin.y + marker.at.y);
    const ImU32 colour = view.selected == Target::Light ? IM_COL32(255, 220, 60, 255) : IM_COL32(255, 240, 180, 220);
    // The light's shape where it is sized and wholly in front of the camera: its outline, and for a
    // flat light the way it faces.
    const LightOutline outline = light_outline(view.scene.camera, view.scene.light, {shown.x, shown.y});
    if (!outline.points.empty()) {
        std::vector<ImVec2> points;
        for (const glm::vec2 p : outline.points) points.emplace_back(origin.x + p.x, origin.y + p.y);
        list->AddPolyline(points.data(), static_cast<int>(points.size()), colour, ImDrawFlags_Closed, 2.0f);
        if (outline.flat)
            list->AddLine(ImVec2(origin.x + outline.centre.x, origin.y + outline.centre.y), ImVec2(origin.x + outline.facing.x, origin.y + outline.facing.y),
                          colour, 1.5f);
    }
    list->AddCircleFilled(at, r, colour);
    list->AddCircle(at, r, IM_COL32(0, 0, 0, 200), 0, 1.5f);
    if (marker.on_screen) {
        for (int i = 0; i < 8; ++i) {
            const float angle = static_cast<float>(i) * 0.785398f;
            const ImVec2 d(std::cos(angle), std::sin(angle));
            list->AddLine(ImVec2(at.x + d.x * r * 1.4f, at.y + d.y * r * 1.4f), ImVec2(at.x + d.x * r * 2.0f, at.y + d.y * r * 2.0f), colour, 1.5f);
        }
        list->AddText(ImVec2(at.x + r * 2.2f, at.y - r), colour, "light");
        return;
    }
    // An arrow from the sun towards the light, and where it is, on the side away from the edge.
    const ImVec2 d(marker.direction.x, marker.direction.y), n(-d.y, d.x);
    const ImVec2 tip(at.x + d.x * r * 2.6f, at.y + d.y * r * 2.6f), base(at.x + d.x * r * 1.4f, at.y + d.y * r * 1.4f);
    list->AddTriangleFilled(tip, ImVec2(base.x + n.x * r * 0.8f, base.y + n.y * r * 0.8f), ImVec2(base.x - n.x * r * 0.8f, base.y - n.y * r * 0.8f), colour);
    const char* label = marker.behind ? "light (behind the camera)" : "light (off screen)";
    const ImVec2 size = ImGui::CalcTextSize(label);
    const float x = std::clamp(at.x - d.x * r * 2.0f - size.x * 0.5f - d.x * size.x * 0.5f, origin.x + 2.0f, origin.x + shown.x - size.x - 2.0f);
    const float y = std::clamp(at.y - d.y * r * 2.5f - size.y * 0.5f, origin.y + 2.0f, origin.y + shown.y - size.y - 2.0f);
    list->AddText(ImVec2(x, y), colour, label);
}

std::optional<glm::vec2> ViewMouse::handle(ViewerScene& view, ImVec2 origin, ImVec2 size) {
    ImGuiIO& io = ImGui::GetIO();
    if (!ImGui::IsItemHovered() && !dragging_) return std::nullopt;
    const auto to_ndc = [&](ImVec2 p) { return glm::vec2((p.x - origin.x) / size.x * 2.0f - 1.0f, 1.0f - (p.y - origin.y) / size.y * 2.0f); };
    std::optional<glm::vec2> click;
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
        dragging_ = true;
        moved_ = false;
        last_ = to_ndc(io.MousePos);
    }
    if (dragging_ && ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        const glm::vec2 now = to_ndc(io.MousePos);
        if (glm::length(now - last_) > 1e-4f) {
            view.rotate_selected(math::arcball_rotation(last_, now));
            last_ = now;
            moved_ = true;
        }
    }
    if (dragging_ && ImGui::IsMouseReleased(ImGuiMouseButton_Left)) {
        dragging_ = false;
        if (!moved_) click = glm::vec2((io.MousePos.x - origin.x) / size.x, (io.MousePos.y - origin.y) / size.y);  // a click picks
    }
    if (ImGui::IsItemHovered() && ImGui::IsMouseDragging(ImGuiMouseButton_Right)) {  // move in the view plane
        const float scale = view.scene.camera.pose.distance / size.y * 1.2f;
        view.move_selected(glm::vec3(io.MouseDelta.x * scale, -io.MouseDelta.y * scale, 0.0f));
    }
    if (ImGui::IsItemHovered() && io.MouseWheel != 0.0f)  // camera Z translation = zoom
        view.scene.camera.pose.distance = std::clamp(view.scene.camera.pose.distance * std::pow(0.9f, io.MouseWheel), 0.1f, 100.0f);
    return click;
}

}  // namespace fxview::ui
