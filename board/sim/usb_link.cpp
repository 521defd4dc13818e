// usb_link.cpp - the simulated board's USB host controller (docs/board-ulx3s.md,
// "USB in the simulation").  tests/host/usb_emu.c (its --soc back end) sends
// each transfer libusb submitted (control, bulk OUT, bulk IN; usb_wire.h);
// this turns them into full-speed transactions on the UTMI side of the SoC's
// USB core (LUNA's device, board/soc/usb_core.py), a byte at a time, as a
// host controller and the FPGA's PHY would: SOF every 1 ms, token packets
// with their CRC5, DATA0/DATA1 packets with their CRC16 and data toggles,
// ACK/NAK/STALL handshakes, NAKed transactions retried, a bus reset (SE0)
// before enumeration.  What is not simulated: the line coding below UTMI
// (NRZI, bit stuffing, SYNC and EOP are time only: a packet of N bytes takes
// (N + 1) * 8 bit times plus 3), and the electrical layer.
//
// The usb clock is 12 MHz: one bit time per cycle, a byte every 8 cycles,
// as LUNA's gateware PHY delivers them on the board.
#include "usb_link.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <string>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>
#include <vector>

#include "usb_wire.h"

namespace
{

enum Pid : uint8_t {
    OUT = 0x1,
    IN = 0x9,
    SOF = 0x5,
    SETUP = 0xD,
    DATA0 = 0x3,
    DATA1 = 0xB,
    ACK = 0x2,
    NAK = 0xA,
    STALL = 0xE
};

const uint32_t FRAME = 12000;       // bit times in a 1 ms frame
const uint32_t GUARD = 1200;        // no transaction starts this close to the next SOF
const uint32_t TIMEOUT = 96;        // bit times the host waits for the device's packet
const uint32_t GAP = 4;             // bit times between packets
const uint32_t RESET_SE0 = 12000;   // a bus reset's SE0: 1 ms (USB asks 10 ms; LUNA detects it after 150)
const int MPS = 64;

// USB 2.0 section 8.3.5: CRC5 over the token's 11 bits, CRC16 over a data
// payload; both sent least significant bit first, complemented.
uint8_t crc5(uint32_t v11)
{
    uint8_t c = 0x1F;
    for (int i = 0; i < 11; i++) {
        const unsigned b = (v11 >> i) & 1u;
        c = ((c ^ b) & 1u) ? (uint8_t)((c >> 1) ^ 0x14) : (uint8_t)(c >> 1);
    }
    return (uint8_t)(c ^ 0x1F);
}

uint16_t crc16(const uint8_t *p, size_t n)
{
    uint16_t c = 0xFFFF;
    for (size_t i = 0; i < n; i++) {
        c ^= p[i];
        for (int k = 0; k < 8; k++)
            c = (c & 1u) ? (uint16_t)((c >> 1) ^ 0xA001) : (uint16_t)(c >> 1);
    }
    return (uint16_t)(c ^ 0xFFFF);
}

std::vector<uint8_t> token(Pid pid, uint32_t v11)
{
    const uint32_t f = v11 | (uint32_t)crc5(v11) << 11;
    return { (uint8_t)(pid | (~pid & 0xF) << 4), (uint8_t)f, (uint8_t)(f >> 8) };
}

std::vector<uint8_t> data_packet(bool toggle, const uint8_t *p, size_t n)
{
    const Pid pid = toggle ? DATA1 : DATA0;
    std::vector<uint8_t> v{ (uint8_t)(pid | (~pid & 0xF) << 4) };
    v.insert(v.end(), p, p + n);
    const uint16_t c = crc16(p, n);
    v.push_back((uint8_t)c);
    v.push_back((uint8_t)(c >> 8));
    return v;
}

struct Transfer {
    uint32_t id;
    int type, ep;               // USBW_CONTROL/USBW_BULK, endpoint address
    uint32_t in_len;            // IN: the buffer's length (control: wLength)
    std::vector<uint8_t> out;   // control: setup + OUT data; bulk OUT: the bytes
    std::vector<uint8_t> in;    // received
    size_t done = 0;            // OUT bytes sent
    int stage = 0;              // control: 0 setup, 1 data, 2 status
    int errors = 0;
    bool cancel = false;
};

}   // namespace

struct UsbLink {
    UtmiPins p;
    int lfd = -1, fd = -1;
    std::vector<uint8_t> rxbuf;
    std::string txbuf;
    std::deque<Transfer> ctrl, bulk_out, bulk_in;
    std::deque<uint32_t> resets;   // bus resets asked for (their ids)
    bool frozen = false;
    bool trace = std::getenv("EF_USB_LINK_TRACE") != nullptr;   // every transfer on stderr

    // device state as the host knows it
    uint8_t addr = 0;
    bool tog_out = false, tog_in = false;   // bulk data toggles (0x01, 0x81)
    bool tog_ctl = false;

    // the wire: one packet out, or waiting for one in
    enum { IDLE, SEND, WAIT, RECV, RESET, SETTLE } w = IDLE;
    std::vector<uint8_t> pkt;   // being sent or received
    size_t pos = 0;
    uint32_t t = 0;   // bit times in this wire state
    bool got_byte = false;

    // the transaction in flight
    enum Kind { NONE, T_SOF, T_SETUP, T_OUT, T_IN, T_STATUS_OUT } kind = NONE;
    Transfer *cur = nullptr;
    int phase = 0;
    std::vector<uint8_t> reply;
    bool reply_timeout = false;
    bool prefer_in = false;

    uint64_t cycle = 0, frame_start = 0;
    uint32_t frame_no = 0;
    uint32_t reset_id = 0;

    // figures
    uint64_t transactions = 0, naks = 0, timeouts = 0, bytes_out = 0, bytes_in = 0, sofs = 0, transfers = 0;
    uint64_t data_out = 0, data_in = 0;       // bulk data packets the device ACKed / the host took
    uint64_t zlps = 0, shorts = 0;            // bulk IN: zero-length and other short packets
    uint64_t first_data = 0, last_data = 0;   // usb cycles of the first and last bulk data packet

    void send_msg(uint32_t op, uint32_t id, uint32_t a, uint32_t b, const uint8_t *data, uint32_t len)
    {
        if (fd < 0)
            return;
        usbw_hdr h{ op, id, a, b, len };
        txbuf.append((const char *)&h, sizeof h);
        if (len)
            txbuf.append((const char *)data, len);
    }
    void complete(Transfer &x, int status)
    {
        const bool in = x.type == USBW_BULK ? (x.ep & 0x80) != 0 : (x.out[0] & 0x80) != 0;
        const uint32_t n = in ? (uint32_t)x.in.size() : (uint32_t)(x.type == USBW_BULK ? x.done : x.out.size() - 8);
        send_msg(USBW_COMPLETE, x.id, (uint32_t)status, n, in ? x.in.data() : nullptr, in ? n : 0);
        transfers++;
        if (trace)
            std::fprintf(stderr, "usb_link: %llu: done %u type %d ep %02x status %d bytes %u\n",
                         (unsigned long long)cycle, x.id, x.type, x.ep, status, n);
    }
    void drop_all()
    {
        ctrl.clear(), bulk_out.clear(), bulk_in.clear(), resets.clear();
        cur = nullptr, kind = NONE;
    }
    void on_message(const usbw_hdr &h, const uint8_t *data)
    {
        if (h.op == USBW_SUBMIT) {
            Transfer x;
            x.id = h.id, x.type = (int)(h.a & 0xFF), x.ep = (int)(h.a >> 8 & 0xFF), x.in_len = h.b;
            x.out.assign(data, data + h.len);
            if (x.type == USBW_CONTROL && x.out.size() < 8) {
                send_msg(USBW_COMPLETE, h.id, (uint32_t)USBW_EPROTO, 0, nullptr, 0);
                return;
            }
            if (trace)
                std::fprintf(stderr, "usb_link: %llu: submit %u type %d ep %02x len %u/%u%s\n",
                             (unsigned long long)cycle, x.id, x.type, x.ep, (unsigned)x.out.size(), x.in_len,
                             x.type == USBW_CONTROL ? (x.out[1] == 3   ? " STATUS"
                                                       : x.out[1] == 2 ? " RESET"
                                                                       : "")
                                                    : "");
            (x.type == USBW_CONTROL ? ctrl : (x.ep & 0x80) ? bulk_in : bulk_out).push_back(std::move(x));
        } else if (h.op == USBW_CANCEL) {
            if (trace)
                std::fprintf(stderr, "usb_link: %llu: cancel %u\n", (unsigned long long)cycle, h.id);
            for (auto *q : { &ctrl, &bulk_out, &bulk_in })
                for (auto &x : *q)
                    if (x.id == h.id)
                        x.cancel = true;
        } else if (h.op == USBW_BUS_RESET) {
            resets.push_back(h.id);
        } else if (h.op == USBW_FREEZE) {
            frozen = h.a != 0;
            if (trace)
                std::fprintf(stderr, "usb_link: %llu: freeze %d\n", (unsigned long long)cycle, (int)frozen);
        }
    }
    void poll()
    {
        if (fd < 0 && lfd >= 0) {
            fd = accept4(lfd, nullptr, nullptr, SOCK_NONBLOCK);
            if (fd >= 0) {
                rxbuf.clear(), txbuf.clear();
                drop_all();
                frozen = false;
            }
        }
        if (fd < 0)
            return;
        uint8_t b[65536];
        for (;;) {
            const ssize_t n = read(fd, b, sizeof b);
            if (n > 0) {
                rxbuf.insert(rxbuf.end(), b, b + n);
                continue;
            }
            if (n == 0 || (errno != EAGAIN && errno != EWOULDBLOCK)) {
                close(fd);   // the emulator went away: its transfers with it
                fd = -1;
                drop_all();
                frozen = false;
                return;
            }
            break;
        }
        size_t at = 0;
        while (rxbuf.size() - at >= sizeof(usbw_hdr)) {
            usbw_hdr h;
            std::memcpy(&h, rxbuf.data() + at, sizeof h);
            if (rxbuf.size() - at - sizeof h < h.len)
                break;
            on_message(h, rxbuf.data() + at + sizeof h);
            at += sizeof h + h.len;
        }
        rxbuf.erase(rxbuf.begin(), rxbuf.begin() + (long)at);
        while (!txbuf.empty()) {
            const ssize_t n = write(fd, txbuf.data(), txbuf.size());
            if (n > 0)
                txbuf.erase(0, (size_t)n);
            else
                break;
        }
    }

    // ---- the transaction layer: what to do when the wire is idle
    void start_send(std::vector<uint8_t> v) { pkt = std::move(v), pos = 0, t = 0, w = SEND; }
    void start_wait() { pkt.clear(), t = 0, w = WAIT; }
    // The device's packet (or a timeout) arrived: decide.
    void transaction_step()
    {
        switch (kind) {
        case T_SOF: kind = NONE; return;
        case T_SETUP:
            if (phase == 0) {
                phase = 1;
                start_send(data_packet(false, cur->out.data(), 8));
            } else if (phase == 1) {
                phase = 2;
                start_wait();
            } else {
                finish_handshake();
            }
            return;
        case T_OUT:
        case T_STATUS_OUT:
            if (phase == 0) {
                phase = 1;
                start_send(out_payload());
            } else if (phase == 1) {
                phase = 2;
                start_wait();
            } else {
                finish_handshake();
            }
            return;
        case T_IN:
            if (phase == 0) {
                phase = 1;
                start_wait();
            } else if (phase == 1) {
                phase = 2;
                if (!reply_timeout && reply.size() >= 3 && valid_data(reply)) {
                    start_send({ (uint8_t)(ACK | (~ACK & 0xF) << 4) });
                    return;
                }
                finish_in();
            } else {
                finish_in();
            }
            return;
        default: return;
        }
    }
    std::vector<uint8_t> out_payload()
    {
        if (kind == T_STATUS_OUT)
            return data_packet(true, nullptr, 0);
        if (cur->type == USBW_CONTROL) {
            const size_t total = cur->out.size() - 8, n = std::min<size_t>(MPS, total - cur->done);
            return data_packet(tog_ctl, cur->out.data() + 8 + cur->done, n);
        }
        const size_t n = std::min<size_t>(MPS, cur->out.size() - cur->done);
        return data_packet(tog_out, cur->out.data() + cur->done, n);
    }
    static bool pid_ok(uint8_t b) { return (b & 0xF) == (uint8_t)(~b >> 4 & 0xF); }
    static bool valid_data(const std::vector<uint8_t> &r)
    {
        if (!pid_ok(r[0]) || ((r[0] & 0xF) != DATA0 && (r[0] & 0xF) != DATA1))
            return false;
        const uint16_t c = crc16(r.data() + 1, r.size() - 3);
        return r[r.size() - 2] == (uint8_t)c && r[r.size() - 1] == (uint8_t)(c >> 8);
    }
    int handshake() const   // the device's handshake: ACK, NAK, STALL, or -1 (none, garbled)
    {
        if (reply_timeout || reply.size() != 1 || !pid_ok(reply[0]))
            return -1;
        const int p = reply[0] & 0xF;
        return p == ACK || p == NAK || p == STALL ? p : -1;
    }
    void error_retry(int status)
    {
        timeouts++;
        if (++cur->errors >= 3)
            finish(status);
    }
    void finish(int status)   // the transfer ends
    {
        Transfer x = std::move(*cur);
        auto *q = x.type == USBW_CONTROL ? &ctrl : (x.ep & 0x80) ? &bulk_in : &bulk_out;
        q->pop_front();
        cur = nullptr;
        complete(x, status);
    }
    void finish_handshake()   // after SETUP, OUT or the OUT status stage
    {
        kind_done();
        const int h = handshake();
        if (h == NAK) {
            naks++;
            return;
        }
        if (h == STALL) {
            finish(USBW_EPIPE);
            return;
        }
        if (h != ACK) {
            error_retry(USBW_EPROTO);
            return;
        }
        cur->errors = 0;
        Transfer &x = *cur;
        if (x.type == USBW_BULK) {
            const size_t n = std::min<size_t>(MPS, x.out.size() - x.done);
            x.done += n, bytes_out += n, tog_out = !tog_out;
            note_data(data_out);
            if (x.done == x.out.size())
                finish(USBW_OK);
            return;
        }
        // control
        const bool dir_in = (x.out[0] & 0x80) != 0;
        if (x.stage == 0) {
            tog_ctl = true;
            x.stage = (dir_in || x.out.size() > 8) ? 1 : 2;
            return;
        }
        if (x.stage == 1) {   // an OUT data stage packet
            const size_t total = x.out.size() - 8, n = std::min<size_t>(MPS, total - x.done);
            x.done += n, tog_ctl = !tog_ctl;
            if (x.done == total)
                x.stage = 2;
            return;
        }
        control_done(x);   // the OUT status stage of an IN request
    }
    void control_done(Transfer &x)
    {
        // what the kernel notes about the device: its address, its configuration's toggles
        const uint8_t *s = x.out.data();
        const unsigned wvalue = s[2] | s[3] << 8;
        if (s[0] == 0x00 && s[1] == 5)
            addr = (uint8_t)(wvalue & 0x7F);
        if ((s[0] == 0x00 && s[1] == 9) || (s[0] == 0x02 && s[1] == 1))   // SET_CONFIGURATION, CLEAR_FEATURE(halt)
            tog_out = tog_in = false;
        finish(USBW_OK);
    }
    void finish_in()   // after an IN token: data (ACKed), NAK, STALL or nothing
    {
        kind_done();
        if (reply_timeout || reply.empty()) {
            error_retry(USBW_EPROTO);
            return;
        }
        if (reply.size() == 1) {
            const int h = handshake();
            if (h == NAK) {
                naks++;
                return;
            }
            if (h == STALL) {
                finish(USBW_EPIPE);
                return;
            }
            error_retry(USBW_EPROTO);
            return;
        }
        if (!valid_data(reply)) {
            error_retry(USBW_EPROTO);
            return;
        }
        cur->errors = 0;
        Transfer &x = *cur;
        const bool t1 = (reply[0] & 0xF) == DATA1;
        const size_t n = reply.size() - 3;
        const uint8_t *d = reply.data() + 1;
        if (x.type == USBW_BULK) {
            if (t1 != tog_in)
                return;   // a repeat of a packet whose ACK the device missed: ACKed, not taken
            tog_in = !tog_in;
            const size_t room = x.in_len - x.in.size(), take = std::min(n, room);
            x.in.insert(x.in.end(), d, d + take);
            bytes_in += take;
            note_data(data_in);
            if (n == 0)
                zlps++;
            else if (n < (size_t)MPS)
                shorts++;
            if (n < (size_t)MPS || x.in.size() == x.in_len || take < n)
                finish(take < n ? USBW_EPROTO : USBW_OK);   // babble when the packet overflows
            return;
        }
        if (x.stage == 1) {   // the IN data stage
            if (t1 != tog_ctl)
                return;
            tog_ctl = !tog_ctl;
            const size_t room = x.in_len - x.in.size(), take = std::min(n, room);
            x.in.insert(x.in.end(), d, d + take);
            if (n < (size_t)MPS || x.in.size() == x.in_len)
                x.stage = 2;
            return;
        }
        // the IN status stage (a zero-length DATA1) of an OUT or no-data request
        control_done(x);
    }
    void kind_done() { kind = NONE; }
    void note_data(uint64_t &count)
    {
        count++;
        if (!first_data)
            first_data = cycle;
        last_data = cycle;
    }

    // Picks the next transaction, or nothing (the wire stays idle).
    void schedule()
    {
        // cancelled transfers end first, with what they have
        for (auto *q : { &ctrl, &bulk_out, &bulk_in })
            for (size_t i = 0; i < q->size(); i++)
                if ((*q)[i].cancel) {
                    Transfer x = std::move((*q)[i]);
                    q->erase(q->begin() + (long)i);
                    complete(x, USBW_ECANCELED);
                    i--;
                }
        const uint64_t in_frame = cycle - frame_start;
        if (in_frame >= FRAME) {
            frame_start = cycle;
            frame_no = (frame_no + 1) & 0x7FF;
            if (*p.term_select) {
                kind = T_SOF, phase = 0, sofs++;
                start_send(token(SOF, frame_no));
            }
            return;
        }
        if (!resets.empty() && bulk_out.empty()) {   // what went out before the replug arrives first
            if (!*p.term_select)
                return;   // no device on the bus yet (its pull-up is off)
            reset_id = resets.front();
            resets.pop_front();
            w = RESET, t = 0;
            return;
        }
        if (!*p.term_select || FRAME - in_frame < GUARD)
            return;
        Transfer *x = nullptr;
        if (!ctrl.empty()) {
            x = &ctrl.front();
        } else {
            const bool in = prefer_in ? !bulk_in.empty() : bulk_out.empty() && !bulk_in.empty();
            if (in)
                x = &bulk_in.front();
            else if (!bulk_out.empty())
                x = &bulk_out.front();
            prefer_in = !prefer_in;
        }
        if (!x)
            return;
        cur = x, phase = 0, transactions++;
        const unsigned epn = (unsigned)(x->ep & 0xF);
        if (x->type == USBW_CONTROL) {
            const bool dir_in = (x->out[0] & 0x80) != 0;
            if (x->stage == 0) {
                kind = T_SETUP;
                start_send(token(SETUP, addr | epn << 7));
            } else if (x->stage == 1) {
                kind = dir_in ? T_IN : T_OUT;
                start_send(token(dir_in ? IN : OUT, addr | epn << 7));
            } else {
                kind = dir_in ? T_STATUS_OUT : T_IN;
                start_send(token(dir_in ? OUT : IN, addr | epn << 7));
            }
        } else {
            const bool dir_in = (x->ep & 0x80) != 0;
            kind = dir_in ? T_IN : T_OUT;
            start_send(token(dir_in ? IN : OUT, addr | epn << 7));
        }
    }

    // ---- the wire, one bit time per call
    void drive()
    {
        *p.rx_valid = 0;
        *p.tx_ready = 0;
        *p.rx_error = 0;
        got_byte = false;
        switch (w) {
        case IDLE:
            *p.rx_active = 0;
            *p.line_state = 2;   // J
            schedule();
            if (w == IDLE || w == RESET)
                break;
            [[fallthrough]];
        case SEND:
            // SYNC (8 bit times), then a byte every 8, then the EOP (3)
            *p.rx_active = 1;
            *p.line_state = 1;   // K (the line is busy)
            if (t >= 8 && t % 8 == 0 && pos < pkt.size()) {
                *p.rx_data = pkt[pos++];
                *p.rx_valid = 1;
            }
            if (pos == pkt.size() && t >= 8 * (pkt.size() + 1) + 3) {
                *p.rx_active = 0;
                *p.line_state = 2;
                w = SETTLE, t = 0;
                return;
            }
            t++;
            break;
        case SETTLE:   // the inter-packet gap after the host's packet
            *p.rx_active = 0;
            *p.line_state = 2;
            if (++t >= GAP) {
                w = IDLE;
                if (kind != NONE)
                    transaction_step();
            }
            break;
        case WAIT:   // for the device's packet
            *p.line_state = 2;
            t++;
            break;
        case RECV:
            t++;
            if (t % 8 == 0)
                *p.tx_ready = 1;
            break;
        case RESET:
            *p.rx_active = 0;
            *p.line_state = t < RESET_SE0 ? 0 : 2;   // SE0, then J
            if (++t >= RESET_SE0 + 200) {
                addr = 0, tog_out = tog_in = false;
                send_msg(USBW_BUS_RESET, reset_id, 0, 0, nullptr, 0);
                w = IDLE;
            }
            break;
        }
    }
    void sample()
    {
        cycle++;
        if (w == WAIT) {
            if (*p.tx_valid) {
                w = RECV, t = 0, pkt.clear();
            } else if (t > TIMEOUT) {
                reply.clear(), reply_timeout = true;
                w = IDLE;
                transaction_step();
            }
            return;
        }
        if (w == RECV) {
            if (*p.tx_ready) {
                if (*p.tx_valid) {
                    pkt.push_back(*p.tx_data);
                } else {
                    reply = pkt, reply_timeout = false;
                    w = SETTLE, t = 0;   // the EOP and the gap, then the next step
                    return;
                }
            }
        }
    }
};

UsbLink *usb_link_new(const char *path, UtmiPins pins)
{
    auto *u = new UsbLink;
    u->p = pins;
    *pins.line_state = 2;
    u->lfd = socket(AF_UNIX, SOCK_STREAM | SOCK_NONBLOCK, 0);
    sockaddr_un sa;
    std::memset(&sa, 0, sizeof sa);
    sa.sun_family = AF_UNIX;
    if (u->lfd < 0 || std::strlen(path) >= sizeof sa.sun_path) {
        std::perror("board_sim: usb socket");
        delete u;
        return nullptr;
    }
    std::strcpy(sa.sun_path, path);
    unlink(path);
    if (bind(u->lfd, (sockaddr *)&sa, sizeof sa) != 0 || listen(u->lfd, 1) != 0) {
        std::perror("board_sim: usb bind/listen");
        delete u;
        return nullptr;
    }
    return u;
}

void usb_link_poll(UsbLink *u) { u->poll(); }
void usb_link_drive(UsbLink *u) { u->drive(); }
void usb_link_sample(UsbLink *u) { u->sample(); }
bool usb_link_frozen(const UsbLink *u) { return u->frozen; }

void usb_link_report(const UsbLink *u, double sim_s, double wall_s)
{
    // the bulk data packets alone, from the first to the last (12 MHz usb cycles)
    const double span = (double)(u->last_data - u->first_data) / 12e6;
    if (u->data_out + u->data_in)
        std::fprintf(stderr,
                     "board_sim: usb: %llu bulk OUT and %llu bulk IN data packets in %.4f s of board time from the "
                     "first to the last (%.0f packets, %.0f bytes per simulated s; %.1f packets per wall s); IN bursts "
                     "ended by %llu short and %llu zero-length packets\n",
                     (unsigned long long)u->data_out, (unsigned long long)u->data_in, span,
                     span > 0 ? (u->data_out + u->data_in) / span : 0.0,
                     span > 0 ? (u->bytes_out + u->bytes_in) / span : 0.0,
                     wall_s > 0 ? (u->data_out + u->data_in) / wall_s : 0.0, (unsigned long long)u->shorts,
                     (unsigned long long)u->zlps);
    std::fprintf(
        stderr,
        "board_sim: usb: %llu transfers, %llu transactions (%.0f per simulated s, %.0f per wall s), %llu NAKed, "
        "%llu without answer, %llu SOFs, %llu bytes out, %llu bytes in (%.0f B per simulated s)\n",
        (unsigned long long)u->transfers, (unsigned long long)u->transactions,
        sim_s > 0 ? u->transactions / sim_s : 0.0, wall_s > 0 ? u->transactions / wall_s : 0.0,
        (unsigned long long)u->naks, (unsigned long long)u->timeouts, (unsigned long long)u->sofs,
        (unsigned long long)u->bytes_out, (unsigned long long)u->bytes_in,
        sim_s > 0 ? (u->bytes_out + u->bytes_in) / sim_s : 0.0);
}

void usb_link_free(UsbLink *u)
{
    if (u->fd >= 0)
        close(u->fd);
    if (u->lfd >= 0)
        close(u->lfd);
    delete u;
}
