/*
 * transport_stream.h - what every byte-stream transport shares (docs/board.md
 * section 5.5): one file descriptor carrying the frames of section 2 both
 * ways, identify/status/reset as control frames in the same stream, and a
 * streaming scanner that takes the control replies out of what the board sends
 * and passes every other byte to host_link in order.  The socket transport
 * (a unix or TCP socket) and the serial transport (a tty) are this layer plus
 * how they open their descriptor.
 *
 * Every wait is bounded by poll() and the timeout.  The end of the stream,
 * a hang-up and the errors in ef_stream_gone's list are EF_HOST_ENODEV (the
 * board went away: the run is resumable).
 */
#ifndef EF_TRANSPORT_STREAM_H
#define EF_TRANSPORT_STREAM_H

#include <stddef.h>
#include <stdint.h>

enum { EF_STREAM_CTL_PAYLOAD_MAX = 64 };

typedef struct ef_stream {
    int fd, timeout_ms, gone;
    int socket; /* 1: send()/recv() (no SIGPIPE); 0: write()/read() (a tty) */
    char addr[300];
    char err[400];
    uint8_t *in; /* bytes from the board: [0, pass) for host_link, [pass, len) not yet scanned */
    size_t pass, len, cap;
    size_t skip;   /* bytes of a non-control frame still to pass through unscanned */
    uint32_t tag;  /* the last control request's tag */
    int want_type; /* reply type awaited (0: none) */
    int got;       /* the awaited reply arrived */
    uint8_t reply[EF_STREAM_CTL_PAYLOAD_MAX];
    uint32_t reply_len;
} ef_stream;

/* Sets the fields to their idle values (fd -1); addr names the link in messages. */
void ef_stream_init(ef_stream *s, const char *addr, int timeout_ms, int socket);
/* One control request (identify 0x10, status 0x11, reset 0x12): up to four
 * tries with a new tag each; the reply's want_len bytes into out. */
int ef_stream_control(ef_stream *s, int type, uint8_t *out, uint32_t want_len);
/* The transport operations on the stream (transport.h's write, flush, read). */
int ef_stream_write(ef_stream *s, const uint8_t *buf, size_t len, int timeout_ms);
int ef_stream_flush(ef_stream *s);
int ef_stream_read(ef_stream *s, uint8_t *buf, size_t cap, size_t *got, int timeout_ms);
/* Closes the descriptor and frees the buffers (not s itself). */
void ef_stream_close(ef_stream *s);
/* The transport operations themselves, for a link whose first member is its
 * ef_stream (the socket's and the serial line's tables). */
struct ef_link;
int ef_stream_op_identify(struct ef_link *l, uint8_t out[48]);
int ef_stream_op_status(struct ef_link *l, uint8_t out[40]);
int ef_stream_op_reset(struct ef_link *l);
int ef_stream_op_write(struct ef_link *l, const uint8_t *buf, size_t len, int timeout_ms);
int ef_stream_op_flush(struct ef_link *l, int timeout_ms);
int ef_stream_op_read(struct ef_link *l, uint8_t *buf, size_t cap, size_t *got, int timeout_ms);
const char *ef_stream_op_detail(struct ef_link *l);
long long ef_stream_now_ms(void);

#endif /* EF_TRANSPORT_STREAM_H */
