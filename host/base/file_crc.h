/*
 * file_crc.h — the CRC-32 (zlib) of a file's bytes, which generated headers
 * quote to name exactly the scene and mesh files they came from.
 */
#ifndef TF_FILE_CRC_H
#define TF_FILE_CRC_H

#include <stdint.h>

/* Returns 0, or -1 when the file cannot be read. */
int tf_file_crc32(const char *path, uint32_t *crc);

#endif /* TF_FILE_CRC_H */
