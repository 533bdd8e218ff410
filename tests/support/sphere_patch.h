// SpherePatch: the directions at polar angle θ ≤ thetaMax about an axis, and ∫ g dω over them by the midpoints of a
// θ × φ grid. Centred on a lobe's or a light's axis, where densities crowd (a cone's is singular there), the
// measure sin θ dθ dφ keeps the integral accurate. Host code for tests.
#pragma once

#include <cmath>

#include "core/vec3.h"
#include "shading/scattering.h"

namespace trazo::test {

struct SpherePatch {
    Vec3 axis{0.0f, 0.0f, 1.0f};
    float thetaMax = 3.14159265358979f;

    Vec3 at(double theta, double phi) const {
        const ConeFrame f = coneFrame(axis);
        return normalize(f.axis * float(std::cos(theta)) +
                         (f.t1 * float(std::cos(phi)) + f.t2 * float(std::sin(phi))) * float(std::sin(theta)));
    }

    template <class G>
    double integral(G&& g, int thetaCells = 600, int phiCells = 600) const {
        double sum = 0.0;
        const double dTheta = thetaMax / thetaCells, dPhi = 2.0 * M_PI / phiCells;
        for (int i = 0; i < thetaCells; ++i) {
            const double theta = (i + 0.5) * dTheta;
            for (int j = 0; j < phiCells; ++j) sum += g(at(theta, (j + 0.5) * dPhi)) * std::sin(theta);
        }
        return sum * dTheta * dPhi;
    }
};

}  // namespace trazo::test
