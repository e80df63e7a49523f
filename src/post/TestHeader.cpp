#include "post/TestHeader.hpp"

#include "post/PythonFormat.hpp"

namespace ma {

TestHeader::TestHeader(const std::string& kind, const std::string& name)
    : labels_(ljust("---- " + kind, 21)), values_(ljust("     " + ljust(name, 8), 21)) {
    fields_.emplace_back(kind == "TABLE" ? "TABLE" : kind == "RESULTAT" ? "RESULTAT" : "CHAM_GD", name);
}

// Pieces appended one by one: gcc 12's -Wrestrict misfires on operator+ chains of short strings.
void TestHeader::add(const std::string& label, const std::string& value) {
    labels_.append(" ").append(ljust(label, 16));
    values_.append(" ").append(ljust(value.substr(0, 16), 16));
    fields_.emplace_back(label, value);
}

std::string TestHeader::text(bool labelBlank) const {
    std::string out = labelBlank ? " " : "";
    return out.append(rstrip(labels_)).append("\n ").append(rstrip(values_)).append("\n");
}

std::string TestHeader::describe() const {
    std::string out;
    for (const auto& [label, value] : fields_) out += (out.empty() ? "" : " ") + label + "=" + value;
    return out;
}

}  // namespace ma
