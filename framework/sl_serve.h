/* sl_serve: the viewer in a browser (shadowlab --serve PORT), for
 * containers, Codespaces and SSH, where no window can open.
 *
 * The viewer renders offscreen as usual; this module serves a page
 * (framework/serve/index.html) and a WebSocket through libwebsockets. Frames
 * go to the page as JPEG, made only when a page has taken the last one, so a
 * slow connection drops frames instead of queueing them; the page sends back
 * keys (pressed and released, as GLFW key codes), drags and the wheel, which
 * the viewer feeds into the same handlers a window's events reach. Which keys
 * the page takes, and what it lists, come from the viewer's own key table,
 * sent to each page as it connects (sl_serve_desc.hello).
 *
 * Only localhost is bound unless an address is given, and only the URL the
 * server prints gets in: it carries a random token (?token=, 192 bits),
 * which the page and its WebSocket must present. A request must also name
 * this machine in its Host header (not a name a web page has pointed at
 * 127.0.0.1) and, with an Origin, come from that same host; anything else
 * gets a 403 and is never counted as a page (sl_serve.c says why each).
 *
 * Built where libwebsockets was found (SL_HAVE_SERVE); elsewhere
 * sl_serve_start says it is not built in. One server per process; its calls
 * come from the render thread, its network from a thread of its own. */
#ifndef SL_SERVE_H
#define SL_SERVE_H

#include <stdbool.h>
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct sl_serve sl_serve;

typedef struct sl_serve_desc {
    int port;                 /* 1-65535 */
    const char *address;      /* the address to bind; default "127.0.0.1" */
    const char *page_dir;     /* the folder holding index.html; default <framework>/serve */
    int jpeg_quality;         /* default 85 */
    const char *hello;        /* JSON sent to each page as it connects, before any frame (the viewer's key
                                 table: framework/serve/index.html reads it); NULL: none */
} sl_serve_desc;

/* What goes with a frame besides its pixels. */
typedef struct sl_serve_frame_desc {
    const char *text;          /* the overlay in words; NULL: none */
    int lab;                   /* the lab in use (the page lists its keys) */
    unsigned long keys_acted;  /* key presses the viewer has acted on so far (the test counts them) */
} sl_serve_frame_desc;

typedef enum sl_serve_event_kind {
    SL_SERVE_KEY_DOWN = 1, /* key: a GLFW key code */
    SL_SERVE_KEY_UP,
    SL_SERVE_BUTTON_DOWN,  /* the left button pressed at x, y (frame pixels, top left origin) */
    SL_SERVE_BUTTON_UP,
    SL_SERVE_MOVE,         /* the pointer at x, y */
    SL_SERVE_WHEEL,        /* y: steps, up positive (GLFW's scroll) */
} sl_serve_event_kind;

typedef struct sl_serve_event {
    sl_serve_event_kind kind;
    int key;
    double x, y;
} sl_serve_event;

/* The browser's KeyboardEvent.code for a GLFW key code (the key's place on a
 * US layout, as GLFW names keys): "KeyV", "Digit1", "BracketLeft", "PageUp";
 * "" for a key the page does not take. For the key tables sent as `hello`. */
const char *sl_serve_key_code(int glfw_key, char code[16]);

/* Whether this build has the server (libwebsockets). */
bool sl_serve_available(void);
/* Starts serving; NULL with the reason in err (not built in, port taken). */
sl_serve *sl_serve_start(const sl_serve_desc *desc, char *err, size_t err_size);
void sl_serve_stop(sl_serve *serve);
/* The URL to open, token included: "http://127.0.0.1:8080/?token=<48 hex digits>" */
const char *sl_serve_url(const sl_serve *serve);

/* Takes up to `max` events that arrived since the last call, oldest first. */
int sl_serve_poll(sl_serve *serve, sl_serve_event *events, int max);
/* Whether a key is held on the page (GLFW key code), for keys polled every
 * frame (lab 6's flying). */
bool sl_serve_key_down(sl_serve *serve, int key);

/* Reads the frame from framebuffer `target` (width x height), compresses it
 * and hands it to the pages with `desc`'s text and numbers - only when a
 * page is ready for one; otherwise it does nothing. Every event
 * polled before the call is reflected in the frame (the page measures its
 * key-to-frame latency by that). False with the reason on a failure. */
bool sl_serve_frame(sl_serve *serve, unsigned target, int width, int height, const sl_serve_frame_desc *desc,
                    char *err, size_t err_size);
/* With no page connected, waits a little (up to 100 ms) so an idle server
 * does not render at full speed for nobody. */
void sl_serve_idle(sl_serve *serve);

#ifdef __cplusplus
}
#endif
#endif
