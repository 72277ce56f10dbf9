/*
 * kinematics.h — strain measures of a deformation gradient and the Voigt
 * notation shared by the material laws (material.h).
 *
 * Tensors are 3 x 3 row major: F[3i + j] = dx_i / dX_j.  Voigt order is
 * elasticity.h's [xx, yy, zz, yz, xz, xy]: stresses and tangents use the
 * tensor components, strains the engineering shears (2 E_yz, ...), so that
 * dS_I = C_IJ dE_J and S_I dE_I is the work per unit volume.
 */
#ifndef TF_KINEMATICS_H
#define TF_KINEMATICS_H

/* Row and column of Voigt index I. */
extern const int tf_voigt_i[6], tf_voigt_j[6];

/* Green-St. Venant strain E = (F^T F - I) / 2 (tensor).  Seed 004 eq 4
 * prints it as grad u + grad u^T + grad u grad u^T, without the 1/2 and
 * with the product transposed; this is the standard form. */
void tf_green_lagrange(const double F[9], double E[9]);

/* Small strain eps = sym(F - I) (tensor). */
void tf_small_strain(const double F[9], double eps[9]);

/* Symmetric tensor -> Voigt: tensor components (stresses), or engineering
 * shears (strains). */
void tf_voigt_stress(const double t[9], double v[6]);
void tf_voigt_strain(const double t[9], double v[6]);

/* Engineering-shear Voigt strain -> symmetric tensor. */
void tf_tensor_strain(const double v[6], double t[9]);

/* Determinant and transpose-product C = F^T F. */
double tf_det3(const double a[9]);
void tf_right_cauchy_green(const double F[9], double C[9]);

/* Inverse of a symmetric tensor with determinant det (not 0). */
void tf_inverse_sym3(const double a[9], double det, double inv[9]);

/* Tensor product a b (3 x 3). */
void tf_matmul3(const double a[9], const double b[9], double ab[9]);

#endif /* TF_KINEMATICS_H */
