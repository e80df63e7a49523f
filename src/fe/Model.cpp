#include "fe/Model.hpp"

namespace ma {

std::string modelisationName(Modelisation m) {
    switch (m) {
        case Modelisation::D_PLAN: return "D_PLAN";
        case Modelisation::C_PLAN: return "C_PLAN";
        case Modelisation::TRI_D: return "3D";
    }
    return "?";
}

}  // namespace ma
