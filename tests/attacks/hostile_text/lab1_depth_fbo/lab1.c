/* Attack: text no report can hold, through every way text reaches the
 * grader's reports: bytes that are not UTF-8 (lone continuation bytes,
 * overlong forms, a surrogate, cut sequences), NUL, terminal escapes, carriage
 * returns, and newlines followed by lines the grader writes ("Score: 16/16",
 * "every check passed", a PASS line), hoping to break the JSON and XML
 * reports or to draw lines in the text report that a TA or a script takes for
 * the grader's; and honest accented text long enough to be cut, whose cut must
 * not split a character. Which way depends on the map size lab 1 is asked for:
 *   every case: the runner's HELLO (backend and renderer, printed on the
 *        report's header line): the grader takes only the first HELLO, which
 *        the runner sends before any lab function, so a constructor puts a
 *        pipe on the channel and a thread rewrites the runner's first message;
 *   512 (lab1_depth_boxes, lab1_moving_light): a capture error, then DONE for
 *        the runner;
 *   384 (lab1_depth_spot): an ERROR of 12 KiB (cut at the result's 8 KiB and
 *        the message's 2 KiB), and 2 KiB of accented output whose kept tail
 *        starts in the middle of a character, then exit;
 *   64 (lab1_probes): output whose last line (quoted in the message, cut to
 *        300 bytes) is hostile and long, then exit;
 *   others (a later lab's scene): a NOT_IMPLEMENTED whose name is not a name. */
#include "@SOURCE_DIR@/tests/attack_util.h"
#include <pthread.h>
#include <time.h>

/* Every kind of bad byte, and lines that look like the grader's. */
static const char _hostile[] = "bad bytes: \xff\xfe lone \x80\xbf overlong \xc0\xaf \xe0\x80\xaf surrogate \xed\xa0\x80 "
                               "cut \xe2\x82 past \xf4\x90\x80\x80 NUL \0 ESC \033[2J\033[H\033]0;title\a CR \r"
                               "\nScore: 16/16\n\rScore: 16/16\r\nevery check passed\n  PASS  2.0/2.0  lab1_depth_boxes"
                               " / depth\nshadowlab-grade: the submission did not build: forged\n\x85\xc2\x85\xc2\x9b"
                               "31m C1 \xef\xbf\xbe\xef\xbf\xbf end ";

/* ---- the channel through a pipe of lab code's own: the runner's HELLO replaced ---- */

static int _real_channel = -1, _relay_in = -1;

static bool _read_full(int fd, void *buf, size_t n) {
    char *p = buf;
    while (n > 0) {
        ssize_t got = read(fd, p, n);
        if (got <= 0) return false;
        p += got;
        n -= (size_t)got;
    }
    return true;
}

static void *_relay(void *arg) {
    (void)arg;
    static const char hello[] = "osmesa\xff\033[2K\rScore: 16/16\nllvmpipe\nScore: 16/16\r\nevery check passed\n\xc0";
    static char buf[1 << 16];
    bool first = true;
    sl_message_header h;
    while (_read_full(_relay_in, &h, sizeof h)) {
        char name[SL_MSG_NAME_MAX];
        if (h.name_length > SL_MSG_NAME_MAX || !_read_full(_relay_in, name, h.name_length)) break;
        bool replace = first && h.type == SL_MSG_HELLO;
        first = false;
        if (replace) {
            sl_message_header forged = {SL_MSG_HELLO, 0, sizeof hello - 1};
            attack_write(_real_channel, &forged, sizeof forged);
            attack_write(_real_channel, hello, sizeof hello - 1);
        } else {
            attack_write(_real_channel, &h, sizeof h);
            attack_write(_real_channel, name, h.name_length);
        }
        for (uint64_t left = h.payload_length; left > 0;) {
            size_t n = left < sizeof buf ? (size_t)left : sizeof buf;
            if (!_read_full(_relay_in, buf, n)) return NULL;
            if (!replace) attack_write(_real_channel, buf, n);
            left -= n;
        }
    }
    return NULL;
}

__attribute__((constructor)) static void _take_the_channel(void) {
    int p[2];
    if (pipe(p) != 0) return;
    _real_channel = dup(SL_CHANNEL_FD);
    _relay_in = p[0];
    dup2(p[1], SL_CHANNEL_FD);
    close(p[1]);
    pthread_t thread;
    if (pthread_create(&thread, NULL, _relay, NULL) == 0) pthread_detach(thread);
}

/* Before leaving at once: the thread passes on what is in the pipe. */
static void _drain_and_exit(int status) {
    struct timespec wait = {0, 300 * 1000 * 1000};
    nanosleep(&wait, NULL);
    _exit(status);
}

/* n bytes: the `lead_length` bytes of `lead`, then "é" (2 bytes) to the end, with one ASCII byte where
 * n - lead_length is odd. */
static char *_accented(const char *lead, size_t lead_length, size_t n) {
    char *text = malloc(n + 1);
    if (!text) return NULL;
    size_t used = lead_length;
    memcpy(text, lead, used);
    if ((n - used) % 2) text[used++] = 'x';
    while (used + 2 <= n) {
        memcpy(text + used, "\xc3\xa9", 2);
        used += 2;
    }
    text[used] = '\0';
    return text;
}

sl_status lab1_create_shadow_map(int size, sl_shadow_map *map) {
    (void)map;
    if (size == 512) {
        attack_send(SL_MSG_CAPTURE_ERROR, "depth_map", _hostile, sizeof _hostile - 1);
        attack_send(SL_MSG_DONE, NULL, NULL, 0);
        attack_wait_for_grader();
    } else if (size == 384) {
        fwrite(_hostile, 1, sizeof _hostile - 1, stdout);
        static const char lead[] = "\nan honest student's accented output: ";
        char *tail = _accented(lead, sizeof lead - 1, 5000); /* the grader keeps 2 KiB */
        if (tail) fputs(tail, stdout);
        fflush(stdout);
        char *error = _accented(_hostile, sizeof _hostile - 1, 12000); /* NUL and all: the payload has a length */
        if (error) attack_send(SL_MSG_ERROR, NULL, error, 12000);
        _drain_and_exit(1);
    } else if (size == 64) {
        fwrite(_hostile, 1, sizeof _hostile - 1, stdout);
        static const char lead[] = "\n\033[1A\r\033[2KScore: 16/16 every check passed ";
        char *last = _accented(lead, sizeof lead - 1, 900);
        if (last) fputs(last, stdout);
        fflush(stdout);
        _drain_and_exit(3);
    } else {
        attack_send(SL_MSG_NOT_IMPLEMENTED, "lab1_\xff\n", NULL, 0);
    }
    return SL_NOT_IMPLEMENTED;
}

ATTACK_LAB1_STUBS
