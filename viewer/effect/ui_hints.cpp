// Annotations to UI hints, accepting NVIDIA (UIName, UIWidget, UIMin...), DXSAS (SasUiLabel,
// SasUiControl, SasUiMin...) and Maya (lower case) spellings, all case-insensitive.
#include <cmath>
#include <algorithm>
#include <cctype>
#include <map>

#include "core/text.hpp"
#include "effect/parser.hpp"

namespace fxview::effect {
namespace {

enum class Hint { Label, Widget, Min, Max, Step, Group, Order, Unit, Help, Items, AtLeast };

const std::map<std::string, Hint>& hint_names() {
    static const std::map<std::string, Hint> names = {
        {"uiname", Hint::Label},      {"sasuilabel", Hint::Label},      {"label", Hint::Label},
        {"uiwidget", Hint::Widget},   {"sasuicontrol", Hint::Widget},   {"widget", Hint::Widget},
        {"uimin", Hint::Min},         {"sasuimin", Hint::Min},          {"min", Hint::Min},
        {"uimax", Hint::Max},         {"sasuimax", Hint::Max},          {"max", Hint::Max},
        {"uistep", Hint::Step},       {"uistepsize", Hint::Step},       {"step", Hint::Step},
        {"uigroup", Hint::Group},     {"sasuigroup", Hint::Group},      {"group", Hint::Group},
        {"uiorder", Hint::Order},     {"sasuiorder", Hint::Order},      {"order", Hint::Order},
        {"uiunits", Hint::Unit},      {"uiunit", Hint::Unit},           {"sasuiunits", Hint::Unit},
        {"unit", Hint::Unit},         {"units", Hint::Unit},            {"uihelp", Hint::Help},
        {"sasuidescription", Hint::Help}, {"uidescription", Hint::Help}, {"help", Hint::Help},
        {"description", Hint::Help},  {"uiitems", Hint::Items},         {"uilist", Hint::Items},
        {"items", Hint::Items},       {"enum", Hint::Items},            {"uiatleast", Hint::AtLeast}};
    return names;
}

std::vector<std::string> split_items(const std::string& text) {
    std::vector<std::string> items;
    const char separator = text.find('|') != std::string::npos ? '|' : ',';
    size_t start = 0;
    for (size_t i = 0; i <= text.size(); ++i)
        if (i == text.size() || text[i] == separator) {
            std::string item = text.substr(start, i - start);
            item.erase(0, item.find_first_not_of(' '));
            item.erase(item.find_last_not_of(' ') + 1);
            if (!item.empty()) items.push_back(item);
            start = i + 1;
        }
    return items;
}

}  // namespace

UiHints ui_hints_from(const std::vector<Annotation>& annotations) {
    UiHints ui;
    for (const auto& annotation : annotations) {
        const auto found = hint_names().find(to_lower(annotation.name));
        if (found == hint_names().end()) continue;  // other annotations are kept but carry no UI meaning
        const Value& v = annotation.value;
        const auto number = [&]() -> std::optional<double> {
            if (v.is_string || v.numbers.size() != 1)
                throw EffectError(annotation.where, "annotation " + annotation.name + " needs a number");
            return v.numbers[0];
        };
        const auto text = [&]() {
            if (!v.is_string) throw EffectError(annotation.where, "annotation " + annotation.name + " needs a string");
            return v.text;
        };
        switch (found->second) {
            case Hint::Label: ui.label = text(); break;
            case Hint::Widget: ui.widget = to_lower(text()); break;
            case Hint::Min: ui.min = number(); break;
            case Hint::Max: ui.max = number(); break;
            case Hint::Step: ui.step = number(); break;
            case Hint::Group: ui.group = text(); break;
            case Hint::Order: {
                const double order = *number();
                if (!(std::abs(order) <= 1e6)) throw EffectError(annotation.where, "UIOrder must lie in -1e6..1e6");
                ui.order = static_cast<int>(order);
                break;
            }
            case Hint::Unit: ui.unit = text(); break;
            case Hint::Help: ui.help = text(); break;
            case Hint::Items: ui.items = split_items(text()); break;
            case Hint::AtLeast: ui.at_least = text(); break;
        }
    }
    if (ui.min && ui.max && *ui.min > *ui.max) {
        const auto& where = annotations.front().where;
        throw EffectError(where, "UIMin " + std::to_string(*ui.min) + " exceeds UIMax " + std::to_string(*ui.max));
    }
    return ui;
}

}  // namespace fxview::effect
