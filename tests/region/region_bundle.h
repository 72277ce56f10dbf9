/*
 * region_bundle.h — the file that carries random region models, their
 * golden vectors and their two-instrument sequences from the host
 * generator (gen_region.c) to the bit-exact runner (run_region.c) and the
 * instruction-count probe (probe_region.c).  All words little-endian
 * uint32:
 *
 *   "TFR1" n_regions
 *   per region: law model, surface model, each as in bundle.h:
 *                 family n_out n_dims n_coef dims[] coef[] node_ids[]
 *                 check[26] crc32 n_vec in[3 n_vec] status[n_vec]
 *                 out[n_vec * 3 n_out]
 *               pair ticks: n tip2[6 n] status[n] force2[6 n] state2[6 n]
 *                 (tfit_region_pair from two reset states; n = 0 when the
 *                 models are not affine)
 *               surface pairs: n state2[6 n] force2[6 n] status[n]
 *                 out[n * 3 n_out] (tfit_region_surface_pair; n = 0 when
 *                 the surface is not affine)
 */
#ifndef TF_REGION_BUNDLE_H
#define TF_REGION_BUNDLE_H

#define TF_REGION_BUNDLE_MAGIC 0x31524654u /* "TFR1" */

#endif /* TF_REGION_BUNDLE_H */
