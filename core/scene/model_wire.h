/* model_wire.h - private to model_sandbox.c: the model importer's result on the pipe from
 * the child process to the parent (model_wire.c). The format is ours and native-endian
 * (both ends are one binary): an 8-byte length of the rest; the error code, the message,
 * the struct ssg_model_up; then, when there is a model, each mesh's counts and arrays, the
 * materials, the textures and the camera. The receiving side checks every count against
 * the bytes still announced before it allocates, and every index against its mesh. */
#ifndef SSG_MODEL_WIRE_H
#define SSG_MODEL_WIRE_H

#include <sys/types.h>

#include "scene/model.h"

/* How a transfer ended. */
enum ssg_wire_ending {
    SSG_WIRE_OK,      /* the whole result arrived */
    SSG_WIRE_TIMEOUT, /* the deadline passed first */
    SSG_WIRE_ENDED,   /* the child closed the pipe (or died) before the end */
    SSG_WIRE_CORRUPT, /* a count or an index that cannot be */
    SSG_WIRE_NOMEM,   /* the parent could not allocate what was announced */
};

/* The parent's end of one transfer. */
struct ssg_wire {
    int fd;                   /* read end of the pipe */
    pid_t pid;                /* the child, polled with waitpid while waiting */
    double deadline;          /* ssg_wire_now() seconds; 0 = none */
    unsigned long long left;  /* bytes announced and not yet read */
    enum ssg_wire_ending ending;
    int reaped, status;       /* the child was collected by waitpid, and its status */
};

/* A monotonic clock, seconds. */
double ssg_wire_now(void);

/* Writes the result to fd (the child's side). g NULL: no model (an error, or only the up
   axis was asked for). 0 when the pipe broke. */
int ssg_wire_send(int fd, enum ssg_err code, const char *why, const struct ssg_model_up *up,
                  const struct ssg_gltf *g);

/* Reads one result (the parent's side): returns the child's code with its message in why,
   the model in *out (out may be NULL) and the up axis in *up. When the transfer fails,
   w->ending says how and *out is NULL. */
enum ssg_err ssg_wire_receive(struct ssg_wire *w, struct ssg_gltf **out,
                              struct ssg_model_up *up, char *why, size_t why_len);

#endif
