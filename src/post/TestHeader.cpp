#include "post/TestHeader.hpp"

#include "post/PythonFormat.hpp"

namespace ma {

TestHeader::TestHeader(const std::string& kind, const std::string& name)
    : labels_(ljust("---- " + kind, 21)), values_(ljust("     " + ljust(name, 8), 21)) {
    fields_.emplace_back(kind == "TABLE" ? "TABLE" : kind == "RESULTAT" ? "RESULTAT" : "CHAM_GD", name);
}

void TestHeader::add(const std::string& label, const std::string& value) {
    labels_ += ljust(" " + label, 17);
    values_ += ljust(" " + value.substr(0, 16), 17);
    fields_.emplace_back(label, value);
}

std::string TestHeader::text(bool labelBlank) const {
    return (labelBlank ? " " : "") + rstrip(labels_) + "\n " + rstrip(values_) + "\n";
}

std::string TestHeader::describe() const {
    std::string out;
    for (const auto& [label, value] : fields_) out += (out.empty() ? "" : " ") + label + "=" + value;
    return out;
}

}  // namespace ma
