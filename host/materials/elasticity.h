/*
 * elasticity.h — isotropic linear elasticity: the D matrix and stresses.
 *
 * Voigt order [xx, yy, zz, yz, xz, xy] with engineering shear strains, as
 * the seed's operator L (eq 4).  The seed's eq 7 prints D with typos (a
 * row D41 D42 D43 in the shear block, D22 where D11 belongs); this is the
 * textbook form: D11 = E(1-nu)/((1+nu)(1-2nu)), D12 = E nu/((1+nu)(1-2nu)),
 * shear diagonal (D11 - D12)/2 = G.
 */
#ifndef TF_ELASTICITY_H
#define TF_ELASTICITY_H

typedef struct tf_lame {
    double lambda, mu; /* MPa */
} tf_lame;

tf_lame tf_lame_from(double young, double poisson);

/* The 6 x 6 D matrix, row major. */
void tf_dmatrix(double young, double poisson, double d[36]);

/* Voigt strain of a displacement gradient g[i*3+j] = du_i/dx_j. */
void tf_strain(const double g[9], double eps[6]);

/* Stress tensor (row major 3 x 3) of a displacement gradient. */
void tf_stress(const tf_lame *l, const double g[9], double sigma[9]);

/* Stiffness block of a node pair at one quadrature point:
 * k[i*3+j] += w (B_a^T D B_b)_ij, with B from the shape-function gradients
 * a = grad phi_a, b = grad phi_b (seed eq 19).  Written in Lamé form,
 * lambda a_i b_j + mu (a_j b_i + delta_ij a.b), which equals B^T D B for
 * the isotropic D and costs a third of the operations. */
static inline void tf_stiffness_block(const tf_lame *l, double w, const double a[3],
                                      const double b[3], double k[9])
{
    double lw = l->lambda * w, mw = l->mu * w;
    double ab = mw * (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            k[3 * i + j] += lw * a[i] * b[j] + mw * a[j] * b[i] + (i == j ? ab : 0);
        }
    }
}

#endif /* TF_ELASTICITY_H */
