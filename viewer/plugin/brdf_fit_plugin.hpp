// The `brdf-fit` plugin: fits the thesis' Ashikhmin-Shirley model (seed 000 eq. 4.28) to the
// measured BRDF behind one of the effect's samplers and writes cd, cs and ns into three of its
// parameters (docs/plugins.md, docs/fitting.md).
#pragma once
#include <memory>
#include <vector>

#include "plugin/plugin.hpp"

namespace fxview::plugin {

std::unique_ptr<Plugin> create_brdf_fit(const effect::Effect& effect, const effect::PluginDeclaration& declaration,
                                        const std::vector<std::string>& texture_dirs);

}  // namespace fxview::plugin
