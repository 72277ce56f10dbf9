/*
 * file_crc.c — CRC-32 of a file (file_crc.h).
 */
#include "base/file_crc.h"

#include <stdio.h>
#include <zlib.h>

int tf_file_crc32(const char *path, uint32_t *crc)
{
    FILE *f = fopen(path, "rb");
    if (f == NULL) {
        return -1;
    }
    unsigned char buf[8192];
    uLong c = crc32(0L, Z_NULL, 0);
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, f)) > 0) {
        c = crc32(c, buf, (uInt)n);
    }
    int bad = ferror(f);
    fclose(f);
    *crc = (uint32_t)c;
    return bad ? -1 : 0;
}
