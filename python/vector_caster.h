#pragma once
// glm::dvec3 (Lucent's Vec3 and Rgb) as Python sees it: a tuple of three
// floats out, any sequence of three finite numbers in. A non-finite number is
// a ValueError: no NaN or infinity reaches a scene from Python either.
#include <pybind11/pybind11.h>

#include <cmath>
#include <glm/glm.hpp>

namespace pybind11::detail {

template <>
struct type_caster<glm::dvec3> {
    PYBIND11_TYPE_CASTER(glm::dvec3, const_name("tuple[float, float, float]"));

    bool load(handle source, bool) {
        if (!isinstance<sequence>(source) || isinstance<str>(source)) return false;
        const sequence items = reinterpret_borrow<sequence>(source);
        if (items.size() != 3) return false;
        for (size_t i = 0; i < 3; ++i) {
            const object item = items[i];
            if (!PyNumber_Check(item.ptr())) return false;
            const double x = PyFloat_AsDouble(item.ptr());
            if (x == -1.0 && PyErr_Occurred()) {
                PyErr_Clear();
                return false;
            }
            if (!std::isfinite(x)) throw value_error("every component must be a finite number");
            value[int(i)] = x;
        }
        return true;
    }

    static handle cast(const glm::dvec3& v, return_value_policy, handle) { return make_tuple(v.x, v.y, v.z).release(); }
};

}  // namespace pybind11::detail
