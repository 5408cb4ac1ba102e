/* The stream from a runner, taken apart as it arrives (sl_run.c): every
 * length bounded, a capture one the case asked for and only once, nothing
 * after DONE; a break of the rules is the case's protocol error. */
#ifndef SL_RUN_STREAM_H
#define SL_RUN_STREAM_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "sl_case.h"
#include "sl_case_result.h"

#define _SL_CASE_BYTES_MAX ((uint64_t)512 << 20) /* everything one case may send */

typedef struct _sl_stream {
    const sl_case *c;
    sl_case_result *r;
    uint32_t wanted;          /* captures the case asked for */
    uint32_t received;        /* captures that arrived */
    char *buf;
    size_t len, cap;
    uint64_t total;           /* bytes received in all */
    bool done;                /* DONE parsed */
    uint64_t messages;        /* messages taken so far: a HELLO must be the first */
    char stage[64];           /* the lab function running, per the last STAGE */
} _sl_stream;

/* The first break of the rules is the case's protocol error (later ones add nothing). */
void _sl_protocol_error(_sl_stream *s, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* The captures case c's checks ask for (sl_check_captures). */
uint32_t _sl_wanted_captures(const sl_case *c);

/* Takes apart what arrived; false once the stream broke the rules. */
bool _sl_stream_feed(_sl_stream *s, const char *data, size_t n);

/* The stream ended: a message after DONE breaks the rules, a stream without DONE names the lab function it
 * was in; the buffer is freed. */
void _sl_stream_end(_sl_stream *s);

#endif
