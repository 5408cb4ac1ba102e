/* sl_crc32: the CRC-32 that zip and gzip record (ISO 3309, reflected
 * polynomial 0xEDB88320), to check what was extracted against an archive's
 * own records with code of ours, not the reader's that extracted it.
 *     uint32_t crc = 0;
 *     crc = sl_crc32(crc, part1, n1);
 *     crc = sl_crc32(crc, part2, n2);   // the CRC-32 of part1 then part2
 */
#ifndef SL_CRC32_H
#define SL_CRC32_H

#include <stddef.h>
#include <stdint.h>

/* crc: 0 to start, or what the previous call returned. */
uint32_t sl_crc32(uint32_t crc, const void *data, size_t n);

#endif
