#include "fields/Fields.hpp"

namespace ma {

void NodalField::resize(const std::shared_ptr<const Mesh>& m, std::vector<std::string> comps) {
    mesh = m;
    components = std::move(comps);
    values.assign(size_t(m->nodeCount()) * components.size(), 0.0);
    present.assign(values.size(), 0);
}

int NodalField::componentIndex(const std::string& comp) const {
    for (size_t i = 0; i < components.size(); ++i)
        if (components[i] == comp) return static_cast<int>(i);
    return -1;
}

int GaussField::componentIndex(const std::string& comp) const {
    for (size_t i = 0; i < components.size(); ++i)
        if (components[i] == comp) return static_cast<int>(i);
    return -1;
}

std::shared_ptr<NodalField> ResultStep::nodal(const std::string& name) const {
    for (const auto& [n, f] : nodalFields)
        if (n == name) return f;
    return nullptr;
}

std::shared_ptr<GaussField> ResultStep::gauss(const std::string& name) const {
    for (const auto& [n, f] : gaussFields)
        if (n == name) return f;
    return nullptr;
}

}  // namespace ma
