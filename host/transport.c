/*
 * transport.c - what every transport shares: the error strings.
 */
#include "transport.h"

const char *ef_host_strerror(int err)
{
    switch (err) {
    case EF_HOST_OK: return "success";
    case EF_HOST_ENODEV: return "the board went away (unplugged or reset by the system)";
    case EF_HOST_ETIMEDOUT: return "timed out";
    case EF_HOST_EACCESS: return "permission denied";
    case EF_HOST_EIO: return "input/output error";
    case EF_HOST_EPROTO: return "not an edgeflag board, or another protocol version";
    case EF_HOST_ENOTFOUND: return "no board matches";
    case EF_HOST_EAMBIGUOUS: return "several boards match";
    case EF_HOST_EBUSY: return "the board is in use by another program";
    case EF_HOST_ENOMEM: return "out of memory";
    case EF_HOST_EINVAL: return "invalid option value";
    case EF_HOST_EUNSUPPORTED: return "this transport was not built in";
    default: return "unknown error";
    }
}
