/* sl_serve: the viewer's frames and input over HTTP and a WebSocket
 * (libwebsockets). See sl_serve.h. */
#define _POSIX_C_SOURCE 200809L
#include "sl_serve.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sl_gl.h"
#include "sl_image.h"
#include "sl_renderer.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

const char *sl_serve_key_code(int key, char code[16]) {
    code[0] = '\0';
    if (key >= GLFW_KEY_A && key <= GLFW_KEY_Z) snprintf(code, 16, "Key%c", key);
    else if (key >= GLFW_KEY_0 && key <= GLFW_KEY_9) snprintf(code, 16, "Digit%c", key);
    else {
        static const struct { int key; const char *code; } named[] = {
            {GLFW_KEY_COMMA, "Comma"}, {GLFW_KEY_PERIOD, "Period"}, {GLFW_KEY_MINUS, "Minus"},
            {GLFW_KEY_EQUAL, "Equal"}, {GLFW_KEY_LEFT_BRACKET, "BracketLeft"}, {GLFW_KEY_RIGHT_BRACKET, "BracketRight"},
            {GLFW_KEY_LEFT, "ArrowLeft"}, {GLFW_KEY_RIGHT, "ArrowRight"}, {GLFW_KEY_UP, "ArrowUp"},
            {GLFW_KEY_DOWN, "ArrowDown"}, {GLFW_KEY_PAGE_UP, "PageUp"}, {GLFW_KEY_PAGE_DOWN, "PageDown"},
            {GLFW_KEY_ESCAPE, "Escape"}, {GLFW_KEY_TAB, "Tab"}, {GLFW_KEY_SPACE, "Space"},
            {GLFW_KEY_LEFT_SHIFT, "ShiftLeft"}, {GLFW_KEY_RIGHT_SHIFT, "ShiftRight"},
        };
        for (size_t i = 0; i < sizeof named / sizeof named[0]; i++)
            if (named[i].key == key) snprintf(code, 16, "%s", named[i].code);
    }
    return code;
}

#ifndef SL_HAVE_SERVE

bool sl_serve_available(void) { return false; }

sl_serve *sl_serve_start(const sl_serve_desc *desc, char *err, size_t err_size) {
    (void)desc;
    if (err && err_size)
        snprintf(err, err_size, "--serve is not built in: libwebsockets was not found when this build was configured "
                                "(Debian: libwebsockets-dev, which scripts/install-deps.sh installs; then configure "
                                "again)");
    return NULL;
}
void sl_serve_stop(sl_serve *serve) { (void)serve; }
const char *sl_serve_url(const sl_serve *serve) { (void)serve; return ""; }
int sl_serve_poll(sl_serve *serve, sl_serve_event *events, int max) {
    (void)serve, (void)events, (void)max;
    return 0;
}
bool sl_serve_key_down(sl_serve *serve, int key) {
    (void)serve, (void)key;
    return false;
}
bool sl_serve_frame(sl_serve *serve, unsigned target, int width, int height, const sl_serve_frame_desc *desc,
                    char *err, size_t err_size) {
    (void)serve, (void)target, (void)width, (void)height, (void)desc, (void)err, (void)err_size;
    return false;
}
void sl_serve_idle(sl_serve *serve) { (void)serve; }

#else

#include <arpa/inet.h>
#include <cjson/cJSON.h>
#include <fcntl.h>
#include <libwebsockets.h>
#include <pthread.h>
#include <strings.h>
#include <time.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/random.h>
#endif

#define _SL_SERVE_EVENTS 256
#define _SL_SERVE_KEYS 512     /* GLFW key codes are below GLFW_KEY_LAST (348) */
#define _SL_SERVE_MESSAGE_MAX 96 /* the longest input message the page sends */
#define _SL_SERVE_TOKEN_BYTES 24   /* 192 bits; the URL carries them as 48 hex digits */

/* One page's connection. */
typedef struct _sl_client {
    bool counted;        /* in `clients`: only a connection that was established (lws may close one it
                            refused with the same callback, and that must not change the count) */
    unsigned long sent;  /* the frame number it was last sent */
    bool greeted;        /* sent the hello (the key table) */
    char message[_SL_SERVE_MESSAGE_MAX];
    size_t message_len;
} _sl_client;

struct sl_serve {
    struct lws_context *context;
    pthread_t thread;
    bool thread_started;
    volatile int stopping;
    char url[220], page_dir[1100];
    char token[2 * _SL_SERVE_TOKEN_BYTES + 1]; /* the URL's ?token=, hex */
    char address[64];                          /* the address bound */
    unsigned char *hello; /* LWS_PRE bytes, then the hello's text; NULL: none */
    size_t hello_size;
    int jpeg_quality;
    struct lws_protocols protocols[3];

    pthread_mutex_t lock; /* everything below */
    unsigned char *frame; /* LWS_PRE bytes, then the message */
    size_t frame_size;    /* the message's bytes */
    unsigned long frame_number;
    int clients, clients_ready; /* connected; of them, holding the latest frame already */
    sl_serve_event events[_SL_SERVE_EVENTS];
    int event_first, event_count;
    bool keys[_SL_SERVE_KEYS];
    unsigned long input_received, input_polled; /* the page's input numbers */
};

static sl_serve *_sl_the_serve; /* the callbacks' server (one per process) */

bool sl_serve_available(void) { return true; }

const char *sl_serve_url(const sl_serve *serve) { return serve ? serve->url : ""; }

/* "k 1 65 17": a key (1 down, 0 up), its GLFW code, the input number; "b 1 x y
 * n": the button; "p x y n": the pointer; "w dy n": the wheel. */
static void _sl_serve_input(sl_serve *s, const char *message) {
    sl_serve_event e = {0};
    int down = 0;
    unsigned long number = 0;
    if (sscanf(message, "k %d %d %lu", &down, &e.key, &number) == 3 && e.key > 0 && e.key < _SL_SERVE_KEYS) {
        e.kind = down ? SL_SERVE_KEY_DOWN : SL_SERVE_KEY_UP;
    } else if (sscanf(message, "b %d %lf %lf %lu", &down, &e.x, &e.y, &number) == 4) {
        e.kind = down ? SL_SERVE_BUTTON_DOWN : SL_SERVE_BUTTON_UP;
    } else if (sscanf(message, "p %lf %lf %lu", &e.x, &e.y, &number) == 3) {
        e.kind = SL_SERVE_MOVE;
    } else if (sscanf(message, "w %lf %lu", &e.y, &number) == 2) {
        e.kind = SL_SERVE_WHEEL;
    } else {
        return; /* not ours: ignored */
    }
    /* no NaN or absurd positions reach the camera */
    if (!(e.x > -1e6 && e.x < 1e6 && e.y > -1e6 && e.y < 1e6)) return;
    pthread_mutex_lock(&s->lock);
    if (e.kind == SL_SERVE_KEY_DOWN || e.kind == SL_SERVE_KEY_UP) s->keys[e.key] = e.kind == SL_SERVE_KEY_DOWN;
    if (s->event_count < _SL_SERVE_EVENTS) {
        s->events[(s->event_first + s->event_count) % _SL_SERVE_EVENTS] = e;
        s->event_count++;
    } /* else full: a render far behind the page; the event is dropped */
    if (number > s->input_received) s->input_received = number;
    pthread_mutex_unlock(&s->lock);
}

/* Who may connect. The server listens on this machine only, but a web page
 * open in the instructor's browser can still reach 127.0.0.1, so a request
 * must also:
 *  - carry the token the viewer printed in its URL (the page passes it on to
 *    its WebSocket): no other page can know it;
 *  - name this machine in its Host header (localhost, a loopback address, or
 *    the address given to --serve-address): a page on a name of its own that
 *    it points at 127.0.0.1 (DNS rebinding) sends its own name there. The
 *    port is not compared: a forwarded port (ssh -L 9000:127.0.0.1:8080) may
 *    differ, and a rebinding page cannot choose the name;
 *  - when it has an Origin, come from that same host (http://HOST): a
 *    browser sends one with every WebSocket and with a fetch from another
 *    page. A request without one is not a browser's script: a program here
 *    that has the token (it read the printed URL) is let in as a page is. */

/* The token: random bytes from the kernel, as hex. */
static bool _sl_serve_make_token(char *token, size_t size) {
    unsigned char bytes[_SL_SERVE_TOKEN_BYTES];
    size_t got = 0;
#ifdef __linux__
    while (got < sizeof bytes) {
        ssize_t n = getrandom(bytes + got, sizeof bytes - got, 0);
        if (n <= 0) break;
        got += (size_t)n;
    }
#endif
    if (got < sizeof bytes) { /* no getrandom(): the same source through the file */
        int fd = open("/dev/urandom", O_RDONLY | O_CLOEXEC);
        got = 0;
        while (fd >= 0 && got < sizeof bytes) {
            ssize_t n = read(fd, bytes + got, sizeof bytes - got);
            if (n <= 0) break;
            got += (size_t)n;
        }
        if (fd >= 0) close(fd);
    }
    if (got < sizeof bytes || size < 2 * sizeof bytes + 1) return false;
    for (size_t i = 0; i < sizeof bytes; i++) snprintf(token + 2 * i, 3, "%02x", bytes[i]);
    return true;
}

/* Equal strings, in a time that does not depend on where they differ (the
 * token's length is no secret: it is always the same). */
static bool _sl_serve_same_secret(const char *given, const char *token) {
    size_t n = strlen(token), m = strnlen(given, n + 1);
    unsigned char diff = m != n;
    for (size_t i = 0; i < n; i++) diff |= (unsigned char)(token[i] ^ (i < m ? given[i] : 0));
    return diff == 0;
}

/* The request's ?token= is the server's. */
static bool _sl_serve_token_ok(sl_serve *s, struct lws *wsi) {
    char arg[160];
    const char *given = lws_get_urlarg_by_name(wsi, "token=", arg, sizeof arg);
    return given && _sl_serve_same_secret(given, s->token);
}

/* An IP address written out (v4, or v6 without its brackets). */
static bool _sl_serve_is_address(const char *name, bool *loopback) {
    unsigned char a[16];
    if (inet_pton(AF_INET, name, a) == 1) {
        *loopback = a[0] == 127;
        return true;
    }
    if (inet_pton(AF_INET6, name, a) == 1) {
        static const unsigned char one[16] = {[15] = 1};
        *loopback = memcmp(a, one, 16) == 0;
        return true;
    }
    return false;
}

/* The Host header names this machine as the text above says; `host` gets it. */
static bool _sl_serve_host_ok(sl_serve *s, struct lws *wsi, char *host, size_t size) {
    if (lws_hdr_copy(wsi, host, (int)size, WSI_TOKEN_HOST) <= 0) return false;
    char name[256];
    const char *port;
    if (host[0] == '[') { /* [v6]:port */
        const char *close = strchr(host, ']');
        if (!close || (size_t)(close - host) >= sizeof name) return false;
        snprintf(name, sizeof name, "%.*s", (int)(close - host - 1), host + 1);
        port = close + 1;
    } else {
        size_t n = strcspn(host, ":");
        if (n >= sizeof name) return false;
        snprintf(name, sizeof name, "%.*s", (int)n, host);
        port = host + n;
    }
    if (*port == ':') {
        port++;
        if (!*port || strspn(port, "0123456789") != strlen(port)) return false;
    } else if (*port) {
        return false;
    }
    bool loopback = false;
    if (strcasecmp(name, "localhost") == 0) return true;
    if (!_sl_serve_is_address(name, &loopback)) return false; /* a name: only localhost */
    if (loopback) return true;
    /* --serve-address: that address, or with 0.0.0.0 / :: any of this machine's (an address, never a name) */
    return strcmp(s->address, "0.0.0.0") == 0 || strcmp(s->address, "::") == 0 || strcasecmp(s->address, name) == 0;
}

/* No Origin, or http://HOST itself. */
static bool _sl_serve_origin_ok(struct lws *wsi, const char *host) {
    char origin[300];
    if (lws_hdr_total_length(wsi, WSI_TOKEN_ORIGIN) <= 0) return true;
    if (lws_hdr_copy(wsi, origin, sizeof origin, WSI_TOKEN_ORIGIN) <= 0) return false;
    return strncasecmp(origin, "http://", 7) == 0 && strcasecmp(origin + 7, host) == 0;
}

/* NULL: the request may go on; else why it is refused (the 403's text). */
static const char *_sl_serve_refusal(sl_serve *s, struct lws *wsi) {
    char host[300];
    if (!_sl_serve_host_ok(s, wsi, host, sizeof host))
        return "shadowlab --serve answers only at 127.0.0.1, [::1] or localhost (or the address given to "
               "--serve-address): open the URL the viewer printed.\n";
    if (!_sl_serve_origin_ok(wsi, host)) return "shadowlab --serve: another site's page may not connect.\n";
    if (!_sl_serve_token_ok(s, wsi))
        return "shadowlab --serve: the token is missing or wrong: open the URL the viewer printed "
               "(http://127.0.0.1:PORT/?token=...).\n";
    return NULL;
}

/* A 403 with `why` as plain text. Returns what the HTTP callback returns. */
static int _sl_serve_refuse(struct lws *wsi, const char *why) {
    unsigned char buf[LWS_PRE + 1024], *start = buf + LWS_PRE, *p = start, *end = buf + sizeof buf;
    size_t n = strlen(why);
    if (lws_add_http_common_headers(wsi, HTTP_STATUS_FORBIDDEN, "text/plain; charset=utf-8", n, &p, end) ||
        lws_add_http_header_by_name(wsi, (const unsigned char *)"cache-control:", (const unsigned char *)"no-store",
                                    8, &p, end) ||
        lws_finalize_write_http_header(wsi, start, &p, end))
        return -1;
    unsigned char body[LWS_PRE + 400];
    if (n > sizeof body - LWS_PRE) n = sizeof body - LWS_PRE;
    memcpy(body + LWS_PRE, why, n);
    if (lws_write(wsi, body + LWS_PRE, n, LWS_WRITE_HTTP_FINAL) < (int)n) return -1;
    return lws_http_transaction_completed(wsi) ? -1 : 0;
}

/* The page (its one file), to a request that passes _sl_serve_refusal. */
static int _sl_serve_http(struct lws *wsi, enum lws_callback_reasons reason, void *user, void *in, size_t len) {
    sl_serve *s = _sl_the_serve;
    switch (reason) {
    case LWS_CALLBACK_HTTP: {
        const char *why = _sl_serve_refusal(s, wsi);
        if (why) return _sl_serve_refuse(wsi, why);
        const char *uri = in;
        if (strcmp(uri, "/") != 0 && strcmp(uri, "/index.html") != 0) {
            lws_return_http_status(wsi, HTTP_STATUS_NOT_FOUND, NULL);
            return lws_http_transaction_completed(wsi) ? -1 : 0;
        }
        char path[1200];
        snprintf(path, sizeof path, "%s/index.html", s->page_dir);
        /* the URL holds the token: not kept in caches nor sent on as a Referer */
        unsigned char headers[256], *p = headers, *end = headers + sizeof headers;
        if (lws_add_http_header_by_name(wsi, (const unsigned char *)"cache-control:", (const unsigned char *)"no-store",
                                        8, &p, end) ||
            lws_add_http_header_by_name(wsi, (const unsigned char *)"referrer-policy:",
                                        (const unsigned char *)"no-referrer", 11, &p, end))
            return -1;
        int n = lws_serve_http_file(wsi, path, "text/html; charset=utf-8", (const char *)headers, (int)(p - headers));
        if (n < 0 || (n > 0 && lws_http_transaction_completed(wsi))) return -1;
        return 0;
    }
    case LWS_CALLBACK_HTTP_CONFIRM_UPGRADE: {
        /* the WebSocket's request: refused with the page's 403 before it becomes a connection */
        const char *why = _sl_serve_refusal(s, wsi);
        if (!why) return 0;
        return _sl_serve_refuse(wsi, why) < 0 ? -1 : 1;
    }
    default:
        return lws_callback_http_dummy(wsi, reason, user, in, len);
    }
}

static int _sl_serve_callback(struct lws *wsi, enum lws_callback_reasons reason, void *user, void *in, size_t len) {
    sl_serve *s = _sl_the_serve;
    _sl_client *c = user;
    switch (reason) {
    case LWS_CALLBACK_FILTER_PROTOCOL_CONNECTION:
        /* checked already (LWS_CALLBACK_HTTP_CONFIRM_UPGRADE); again here, so no path to a connection skips it */
        return _sl_serve_refusal(s, wsi) ? -1 : 0;
    case LWS_CALLBACK_ESTABLISHED:
        memset(c, 0, sizeof *c);
        pthread_mutex_lock(&s->lock);
        s->clients++;
        c->counted = true;
        pthread_mutex_unlock(&s->lock);
        lws_callback_on_writable(wsi);
        break;
    case LWS_CALLBACK_CLOSED:
        if (!c || !c->counted) break; /* refused before it was established: never counted */
        c->counted = false;
        pthread_mutex_lock(&s->lock);
        s->clients--;
        if (c->sent == s->frame_number && s->frame_number) s->clients_ready--;
        pthread_mutex_unlock(&s->lock);
        break;
    case LWS_CALLBACK_SERVER_WRITEABLE: {
        int status = 0;
        if (!c->greeted) { /* the key table first, as text; frames when the socket is writable again */
            c->greeted = true;
            if (s->hello) {
                if (lws_write(wsi, s->hello + LWS_PRE, s->hello_size, LWS_WRITE_TEXT) < (int)s->hello_size) return -1;
                lws_callback_on_writable(wsi);
                return 0;
            }
        }
        pthread_mutex_lock(&s->lock);
        if (s->frame && c->sent != s->frame_number) {
            /* lws keeps what the socket did not take and calls again only once it is sent */
            if (lws_write(wsi, s->frame + LWS_PRE, s->frame_size, LWS_WRITE_BINARY) < (int)s->frame_size) status = -1;
            c->sent = s->frame_number;
            s->clients_ready++;
        }
        pthread_mutex_unlock(&s->lock);
        return status;
    }
    case LWS_CALLBACK_RECEIVE:
        if (c->message_len + len < sizeof c->message) {
            memcpy(c->message + c->message_len, in, len);
            c->message_len += len;
        } else {
            c->message_len = sizeof c->message; /* too long for any of ours: dropped whole */
        }
        if (lws_is_final_fragment(wsi)) {
            if (c->message_len < sizeof c->message) {
                c->message[c->message_len] = '\0';
                _sl_serve_input(s, c->message);
            }
            c->message_len = 0;
        }
        break;
    case LWS_CALLBACK_EVENT_WAIT_CANCELLED:
        /* a new frame (sl_serve_frame woke the service loop) */
        if (s && s->context) lws_callback_on_writable_all_protocol(s->context, &s->protocols[1]);
        break;
    default:
        break;
    }
    return 0;
}

static void *_sl_serve_thread(void *arg) {
    sl_serve *s = arg;
    while (!s->stopping)
        if (lws_service(s->context, 0) < 0) break;
    return NULL;
}

sl_serve *sl_serve_start(const sl_serve_desc *desc, char *err, size_t err_size) {
    if (_sl_the_serve) {
        snprintf(err, err_size, "one server per process");
        return NULL;
    }
    if (desc->port < 1 || desc->port > 65535) {
        snprintf(err, err_size, "--serve: the port is 1..65535, not %d", desc->port);
        return NULL;
    }
    sl_serve *s = calloc(1, sizeof *s);
    if (!s) {
        snprintf(err, err_size, "out of memory");
        return NULL;
    }
    pthread_mutex_init(&s->lock, NULL);
    s->jpeg_quality = desc->jpeg_quality > 0 ? desc->jpeg_quality : 85;
    const char *address = desc->address && desc->address[0] ? desc->address : "127.0.0.1";
    if (desc->page_dir) snprintf(s->page_dir, sizeof s->page_dir, "%s", desc->page_dir);
    else snprintf(s->page_dir, sizeof s->page_dir, "%s/serve", sl_framework_dir());
    char index[1200];
    snprintf(index, sizeof index, "%s/index.html", s->page_dir);
    FILE *f = fopen(index, "rb");
    if (!f) {
        snprintf(err, err_size, "--serve: the page %s is missing", index);
        free(s);
        return NULL;
    }
    fclose(f);
    if (desc->hello) {
        s->hello_size = strlen(desc->hello);
        s->hello = malloc(LWS_PRE + s->hello_size + 1);
        if (!s->hello) {
            snprintf(err, err_size, "out of memory");
            free(s);
            return NULL;
        }
        memcpy(s->hello + LWS_PRE, desc->hello, s->hello_size + 1);
    }
    if (!_sl_serve_make_token(s->token, sizeof s->token)) {
        snprintf(err, err_size, "--serve: no random bytes for the URL's token (getrandom, /dev/urandom)");
        free(s->hello);
        free(s);
        return NULL;
    }
    snprintf(s->address, sizeof s->address, "%s", address);
    /* The page: index.html alone; the frames and input: the "shadowlab" protocol. */
    s->protocols[0] = (struct lws_protocols){"http", _sl_serve_http, 0, 0, 0, NULL, 0};
    s->protocols[1] = (struct lws_protocols){"shadowlab", _sl_serve_callback, sizeof(_sl_client), 4096, 0, NULL, 0};
    struct lws_context_creation_info info;
    memset(&info, 0, sizeof info);
    info.port = desc->port;
    info.iface = address;
    info.protocols = s->protocols;
    info.gid = -1;
    info.uid = -1;
    if (!strchr(address, ':')) info.options |= LWS_SERVER_OPTION_DISABLE_IPV6;
    lws_set_log_level(LLL_ERR, NULL);
    _sl_the_serve = s;
    s->context = lws_create_context(&info);
    if (!s->context) {
        snprintf(err, err_size, "--serve: cannot listen on %s port %d (taken by another program, or not an "
                                "address of this machine?)", address, desc->port);
        _sl_the_serve = NULL;
        free(s->hello);
        free(s);
        return NULL;
    }
    bool ipv6 = strchr(address, ':') != NULL;
    snprintf(s->url, sizeof s->url, "http://%s%s%s:%d/?token=%s", ipv6 ? "[" : "",
             strcmp(address, "0.0.0.0") == 0 ? "127.0.0.1" : strcmp(address, "::") == 0 ? "::1" : address,
             ipv6 ? "]" : "", desc->port, s->token);
    if (pthread_create(&s->thread, NULL, _sl_serve_thread, s) != 0) {
        snprintf(err, err_size, "--serve: cannot start the server's thread");
        sl_serve_stop(s);
        return NULL;
    }
    s->thread_started = true;
    return s;
}

void sl_serve_stop(sl_serve *s) {
    if (!s) return;
    s->stopping = 1;
    if (s->context) lws_cancel_service(s->context);
    if (s->thread_started) pthread_join(s->thread, NULL);
    if (s->context) lws_context_destroy(s->context);
    free(s->frame);
    free(s->hello);
    pthread_mutex_destroy(&s->lock);
    if (_sl_the_serve == s) _sl_the_serve = NULL;
    free(s);
}

int sl_serve_poll(sl_serve *s, sl_serve_event *events, int max) {
    pthread_mutex_lock(&s->lock);
    int n = 0;
    while (n < max && s->event_count > 0) {
        events[n++] = s->events[s->event_first];
        s->event_first = (s->event_first + 1) % _SL_SERVE_EVENTS;
        s->event_count--;
    }
    if (s->event_count == 0) s->input_polled = s->input_received;
    pthread_mutex_unlock(&s->lock);
    return n;
}

bool sl_serve_key_down(sl_serve *s, int key) {
    if (!s || key <= 0 || key >= _SL_SERVE_KEYS) return false;
    pthread_mutex_lock(&s->lock);
    bool down = s->keys[key];
    pthread_mutex_unlock(&s->lock);
    return down;
}

/* Ready for a frame: some page holds the latest one (or none was made yet). */
static bool _sl_serve_wants(sl_serve *s, unsigned long *input) {
    pthread_mutex_lock(&s->lock);
    bool wants = s->clients > 0 && (s->frame_number == 0 || s->clients_ready > 0);
    *input = s->input_polled;
    pthread_mutex_unlock(&s->lock);
    return wants;
}

bool sl_serve_frame(sl_serve *s, unsigned target, int width, int height, const sl_serve_frame_desc *desc,
                    char *err, size_t err_size) {
    sl_serve_frame_desc none = {0};
    if (!desc) desc = &none;
    unsigned long input = 0;
    if (!s || !_sl_serve_wants(s, &input)) return true;
    size_t stride = (size_t)width * 4;
    unsigned char *pixels = malloc(stride * (size_t)height);
    if (!pixels) {
        snprintf(err, err_size, "out of memory for a %dx%d frame", width, height);
        return false;
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, target);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    sl_pixels p = {pixels, width, height, 4, stride, true};
    unsigned char *jpeg = NULL;
    size_t jpeg_size = 0;
    bool ok = sl_image_encode(&p, "jpg", s->jpeg_quality, &jpeg, &jpeg_size, err, err_size);
    free(pixels);
    if (!ok) return false;
    /* The message: 4 bytes (little-endian length of the header), the header
     * as JSON, the JPEG. */
    cJSON *header = cJSON_CreateObject();
    pthread_mutex_lock(&s->lock);
    double number = (double)(s->frame_number + 1);
    pthread_mutex_unlock(&s->lock);
    cJSON_AddNumberToObject(header, "frame", number);
    cJSON_AddNumberToObject(header, "input", (double)input);
    cJSON_AddNumberToObject(header, "width", width);
    cJSON_AddNumberToObject(header, "height", height);
    cJSON_AddNumberToObject(header, "lab", desc->lab);
    cJSON_AddNumberToObject(header, "keys_acted", (double)desc->keys_acted);
    cJSON_AddStringToObject(header, "text", desc->text ? desc->text : "");
    char *json = cJSON_PrintUnformatted(header);
    cJSON_Delete(header);
    size_t json_size = json ? strlen(json) : 0;
    size_t size = 4 + json_size + jpeg_size;
    unsigned char *message = json ? malloc(LWS_PRE + size) : NULL;
    if (!message) {
        free(json);
        free(jpeg);
        snprintf(err, err_size, "out of memory for a frame");
        return false;
    }
    unsigned char *m = message + LWS_PRE;
    m[0] = (unsigned char)(json_size & 0xff);
    m[1] = (unsigned char)((json_size >> 8) & 0xff);
    m[2] = (unsigned char)((json_size >> 16) & 0xff);
    m[3] = (unsigned char)((json_size >> 24) & 0xff);
    memcpy(m + 4, json, json_size);
    memcpy(m + 4 + json_size, jpeg, jpeg_size);
    free(json);
    free(jpeg);
    /* The newest frame replaces one not yet sent: frames are dropped, never queued. */
    pthread_mutex_lock(&s->lock);
    free(s->frame);
    s->frame = message;
    s->frame_size = size;
    s->frame_number++;
    s->clients_ready = 0;
    pthread_mutex_unlock(&s->lock);
    lws_cancel_service(s->context);
    return true;
}

void sl_serve_idle(sl_serve *s) {
    if (!s) return;
    pthread_mutex_lock(&s->lock);
    int clients = s->clients;
    pthread_mutex_unlock(&s->lock);
    if (clients > 0) return;
    struct timespec wait = {0, 100 * 1000 * 1000};
    nanosleep(&wait, NULL);
}

#endif
