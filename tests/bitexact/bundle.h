/*
 * bundle.h — the file that carries random models and their golden vectors
 * from the host generator (gen_random.c) to the bit-exact runner
 * (run_bundle.c).  All words little-endian uint32:
 *
 *   "TFB2" n_models
 *   per model: family n_out n_dims n_coef dims[n_dims] coef[n_coef] (bits)
 *              node_ids[n_out] check[7] crc32 n_vec in[3 n_vec]
 *              status[n_vec] out[n_vec * 3 n_out]
 * (check[]: the model's self-test vector, tfit.h / header-format.md §8.)
 */
#ifndef TF_BUNDLE_H
#define TF_BUNDLE_H

#define TF_BUNDLE_MAGIC 0x32424654u /* "TFB2" */

#endif /* TF_BUNDLE_H */
