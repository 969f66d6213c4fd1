/* session.h - what `ssgraph view` holds between requests (session.c): the live graph at
 * full size, a second one at preview size for camera drags (loaded on the first drag), the
 * parameter changes made in this session (re-applied after a reload, written by "save as
 * variant"), the camera, the last run's statistics and error, and a generation number
 * that every run and reload raises so that a page knows when to fetch again.
 * Not thread-safe: the server calls it from one thread at a time (server.c holds a lock). */
#ifndef SSG_CLI_VIEW_SESSION_H
#define SSG_CLI_VIEW_SESSION_H

#include <stdio.h>

#include "../options.h"
#include "ssgraph.h"

struct ssg_cli_watch;

enum { VIEW_MAX_SETS = 256, VIEW_KEY_MAX = 128, VIEW_VALUE_MAX = 1024 };

struct view_set {
    char key[VIEW_KEY_MAX];     /* "ao.radius" */
    char value[VIEW_VALUE_MAX]; /* as a graph file writes it ("0.3", "\"name\"") */
};

struct view_session {
    const struct ssg_cli_args *args; /* the command line: graph, overrides, --out */
    struct ssg_graph *g;             /* the last graph that loaded, kept (live) */
    struct ssg_graph *preview;       /* the same at preview size; NULL until a drag */
    int width, height;               /* the full frame (without guard) */
    int preview_width, preview_height;
    struct view_set sets[VIEW_MAX_SETS]; /* this session's changes, one per key, in order */
    int set_count;
    int has_camera, camera_changed;  /* the scene has a camera; the page moved it */
    struct ssg_view camera;          /* the current one */
    struct ssg_run_stats stats;      /* the last run's */
    int last_preview;                /* 1 = the last run was the preview graph's */
    int full_stale;                  /* 1 = the full graph has a camera it has not run
                                        with (after a drag): it runs when asked for */
    int preview_stale;               /* the same of the preview graph (after a set or a
                                        release) */
    unsigned generation;             /* raised by every run and reload */
    int frame;                       /* the frame of the sequence shown (view_session_frame) */
    char *error;                     /* the last failure's diagnostics as printed; NULL */
    struct ssg_cli_watch *watch;     /* the graph's files (watch.h); NULL = none */
    struct ssg_image *ref_file;      /* the open reference file (reference.h); NULL = none */
    char *ref_port;                  /* its name in the port lists, "file:PATH"; NULL */
    char *text;                      /* the graph file's text as edited in the page
                                        (view_session_edit), loaded in its place; NULL =
                                        no edits: the file on disk */
    int edits;                       /* edits made since the text was last saved */
};

/* Loads the graph of args as a live graph and runs it once; on failure the diagnostics are
 * printed to stderr and SSG_E_* is returned (nothing to serve). */
enum ssg_err view_session_open(struct view_session *s, const struct ssg_cli_args *args);
void view_session_close(struct view_session *s);

/* Applies "node.param=value" to the graphs and runs the full one. A refused value leaves
 * everything as it was and puts the reason into diags. */
enum ssg_err view_session_set(struct view_session *s, const char *assignment,
                              struct ssg_diags *diags);
/* A new camera for both graphs; runs the preview graph (preview = 1, loading it on the
 * first call) or the full one. */
enum ssg_err view_session_camera(struct view_session *s, const struct ssg_view *camera,
                                 int preview, struct ssg_diags *diags);
/* Runs frame `frame` of the sequence (docs/time.md: a scene's camera path gives its camera;
 * frame last + 1 follows on, keeping history; any other is a cut) on the full graph. The
 * page's own camera gives way to the path's. */
enum ssg_err view_session_frame(struct view_session *s, int frame, struct ssg_diags *diags);
/* The latest image of "node.port" (of the preview graph with preview = 1) without its
 * guard band, or the open reference file's ("file:PATH", reference.h), as a new image the
 * caller destroys. */
enum ssg_err view_session_image(struct view_session *s, const char *port, int preview,
                                struct ssg_image **out, struct ssg_diags *diags);
/* 1 when the watched files changed since the last load; reloads (the session's sets and
 * camera applied again) and runs then: on failure s->error says why and the last good
 * graph stays. 0 when nothing changed. */
int view_session_poll(struct view_session *s);
/* Writes NAME.graph beside the graph file (variant.c): include, the server's --scene,
 * --lights, --size, --guard and --seed as statements, the command line's and this
 * session's set lines; the path written into path. Never waits on another program and
 * never replaces: SSG_E_IO when the name exists in any form (a FIFO, a dangling link, a
 * directory, a file nobody may read) or cannot be written; SSG_E_USAGE for a bad name or
 * a name or value a graph file cannot hold (diags say which). */
enum ssg_err view_session_save(struct view_session *s, const char *name, char *path,
                               size_t len, struct ssg_diags *diags);

/* Writes NAME.scene beside the graph file (campath.c): `include "<the graph's scene>"` and
 * one camera_key line per key of `keys` ("t,px,py,pz,tx,ty,tz,ux,uy,uz,fov" per key, keys
 * apart by ';', 2 to VIEW_MAX_KEYS of them), whose path replaces the included scene's. The
 * same safety as view_session_save; SSG_E_USAGE for a bad name or key, or no scene. */
enum { VIEW_MAX_KEYS = 1024 };
enum ssg_err view_session_save_path(const struct view_session *s, const char *name,
                                    const char *keys, char *path, size_t len,
                                    struct ssg_diags *diags);

/* What variant.c shares with campath.c. 1 when name is 1 to 64 of [A-Za-z0-9_-]. */
int view_valid_name(const char *name);
/* NAME + ext beside the graph file into path, when the name is good and nothing is there
 * in any form (lstat); else SSG_E_USAGE (the name) or SSG_E_IO (it exists). */
enum ssg_err view_new_path(const struct view_session *s, const char *name, const char *ext,
                          char *path, size_t len, struct ssg_diags *d);
/* 1 when view_quote can write s: its only control characters are a newline and a tab. */
int view_quotable(const char *s);
/* s as a string literal of the graph and scene lexer, with its escapes. */
void view_quote(FILE *f, const char *s);
/* A path the server was given, made absolute against its working folder (malloc'd; NULL
 * when the folder cannot be read). */
char *view_absolute(const char *path);
/* text as a new file at path: a temporary file of our own (O_EXCL), linked to the name,
 * never replacing nor opening what is there (SSG_E_IO, "exists already"). */
enum ssg_err view_write_new(const char *path, const char *text, size_t len,
                            struct ssg_diags *d);

/* Applies `edits` (graph statements one a line: ssg_graph_text_edit) to the graph file's
 * text, the session's edited text if it has one, and loads the result in the file's place
 * with the session's changes and camera, then runs it. Refused, with the graph file's own
 * messages at the line of the edited text and the session as it was, when the edit or the
 * load fails. A node removed takes the session's parameter changes of it along. While the
 * session has edits, a change of the file on disk is not loaded (s->error says so). */
enum ssg_err view_session_edit(struct view_session *s, const char *edits,
                               struct ssg_diags *diags);
/* Drops the edits and loads the graph file from disk again. */
enum ssg_err view_session_discard(struct view_session *s, struct ssg_diags *diags);
/* Writes the edited text as NAME.graph beside the graph file (edit.c), with the command
 * line's and this session's parameter changes written into it as a person would
 * (ssg_graph_text_edit), and the server's --scene, --lights, --size, --guard and --seed as
 * statements at its end; the same rules as view_session_save. SSG_E_USAGE without edits. */
enum ssg_err view_session_save_edited(struct view_session *s, const char *name, char *path,
                                      size_t len, struct ssg_diags *diags);

/* The statements standing for the server's command line, and the page's camera as a
 * comment, which both saves of a graph write (variant.c, edit.c). */
enum ssg_err view_command_line(FILE *f, const struct ssg_overrides *ov,
                               struct ssg_diags *diags);
void view_camera_comment(FILE *f, const struct view_session *s);
/* Closes f, an open_memstream over *text: SSG_E_NOMEM (out of memory for `what`) when the
 * stream failed; on any error e, *text freed and NULL. Returns the error. */
enum ssg_err view_text_close(FILE *f, char **text, enum ssg_err e, const char *what,
                             struct ssg_diags *diags);
/* The parameter changes of the command line and of this session as `set KEY = VALUE`
 * lines; SSG_E_USAGE when a key or value holds a control character (the core refuses such
 * values; this keeps any that got by from becoming a line of its own). */
enum ssg_err view_set_lines(FILE *f, const struct view_session *s, struct ssg_diags *diags);

/* Adds an error without a file position (file "<view>") to d; returns code. */
enum ssg_err view_fail(struct ssg_diags *d, enum ssg_err code, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

/* The diagnostics as `ssgraph run` prints them, as a new string (NULL on out of memory). */
char *view_diags_text(const struct ssg_diags *diags, enum ssg_err e);

#endif
