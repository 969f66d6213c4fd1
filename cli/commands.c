/* commands.c - the table of the command line's commands (commands.h). */
#include "commands.h"
#include "options.h"

const struct ssg_cli_command_info ssg_cli_commands[] = {
    {SSG_CLI_RUN, "run", "FILE", 1, 1,
     "validate and run a graph; writes into --out (default out/)",
     "Validates the graph FILE as a whole, then runs its nodes in dependency order. Each\n"
     "write node writes <out>/<name>.exr (the image and every layer given to it) and\n"
     "<out>/<name>.png (tone-mapped preview); compare nodes add <out>/metrics.json. Each\n"
     "file written is named on a line `wrote PATH` as it is written; then comes the\n"
     "table of every node's time (with --frames N a profile over the frames) and the\n"
     "metrics. -o DIR/NAME.exr names the graph's first write node's output: NAME.exr\n"
     "and NAME.png in DIR, every other file of the run in DIR too (as --out DIR).\n"
     "--show ao.out,g.normal also writes those ports as <out>/ao.out.exr and .png (as a\n"
     "write node of the port would), without a change to the graph."},
    {SSG_CLI_CHECK, "check", "FILE", 1, 1,
     "validate a graph and its scene without running it (FILE.scene:\n"
     "validate a scene and load its meshes; a model file: describe it)",
     "Validates the graph FILE (syntax, nodes, parameters and their ranges, connections,\n"
     "types, sizes, cycles) and its scene file without loading meshes or images, and\n"
     "prints `FILE: ok`. A FILE ending in .scene is validated as a scene, its meshes\n"
     "loaded (each mesh's box after its line's transform, and the model's up axis). A\n"
     "model file (.obj, .ply, .3ds, .gltf... what a scene's mesh line reads) is loaded\n"
     "and described: its meshes, bounds, up axis, and a scene to paste around it.\n"
     "Every problem is reported as FILE:LINE:COLUMN: error: ..."},
    {SSG_CLI_NODE, "node", "NAME", 1, 1,
     "run one node on image files (--in port=file.exr[:layer])",
     "Runs the node NAME alone on image files bound to its input ports, with --set\n"
     "P=VALUE for its parameters, and writes each output as <out>/<port>.exr (-o\n"
     "FILE.exr: the first output as FILE.exr, any other as FILE_<port>.exr beside it);\n"
     "prints `wrote PATH` per file, then the metrics the node reported (compare)."},
    {SSG_CLI_BENCH, "bench", "FILE | --merge DIR...", 1, SSG_CLI_MAX_FILES,
     "run a graph for every combination of --sweep NODE.PARAM=V1,V2,...",
     "Runs the graph FILE for every combination of the --sweep values (up to 4 sweeps),\n"
     "--frames N frames each (default 5), and writes bench.csv, bench.md and bench.json\n"
     "into --out, a row per cell as it finishes. The table shows --time NODE's ms\n"
     "(default: the whole frame); --plot draws ms against the first sweep and --error\n"
     "NODE.METRIC against ms (a Pareto view) as PNG with gnuplot; --reference NODE.PORT\n"
     "--image NODE.PORT adds each cell's error against that truth; --stereo times both\n"
     "eyes of every cell (1080x1200 unless --size). Exit status 1 when a cell failed.\n"
     "--shard I/N runs only every N-th cell from the I-th; `bench --merge DIR... --out\n"
     "DIR` joins the shards of one sweep into the tables an unsharded run writes."},
    {SSG_CLI_COMPARE, "compare", "A B", 2, 2,
     "RMSE, MAE, bias, PSNR, SSIM of image A against reference B",
     "Prints the RMSE, MAE, bias, PSNR and SSIM of image A against the reference B (each\n"
     "FILE or FILE:LAYER of an EXR), one `name value` line each (--json: one line of\n"
     "JSON). For the difference image run `ssgraph node compare --in a=A --in b=B`."},
    {SSG_CLI_TUNE, "tune", "FILE", 1, 1,
     "search --param NODE.P=LO:HI for the lowest error against a reference",
     "Searches the --param ranges of the graph FILE for the lowest mean RMSE of --image\n"
     "NODE.PORT against --reference NODE.PORT (computed once per scene) over every\n"
     "--scene (--mask NODE.PORT: those pixels only; --evals N, default 40). Writes\n"
     "tune.csv and tune.json into --out after each evaluation, and tuned.graph, the\n"
     "graph with the best values."},
    {SSG_CLI_DOT, "dot", "FILE", 1, 1,
     "the graph as Graphviz DOT (to stdout, or -o FILE)",
     "Writes the graph FILE as Graphviz DOT: a box per node with its name and type, an\n"
     "edge per connection labelled `output -> input` (the producer's port, the\n"
     "consumer's input or layer name). Nothing is validated beyond parsing, so a graph\n"
     "that does not check yet can still be drawn:\n"
     "  ssgraph dot graphs/ssdo.graph | dot -Tsvg > ssdo.svg"},
    {SSG_CLI_VIEW, "view", "FILE", 1, 1,
     "look at a graph live in a local web page: any port, parameters, camera",
     "Loads the graph FILE as a live graph, runs it, and serves a web page on 127.0.0.1\n"
     "(--port, default a free one), printing its URL with a random token: open it in a\n"
     "browser on this machine. The page draws the graph (click a node for its\n"
     "parameters and ports), shows any port's image as floats (exposure and the tone\n"
     "curve in a WebGL2 shader, channels, false colour, the value under the mouse),\n"
     "re-runs only what a changed parameter affects and says why each node ran or was\n"
     "kept, orbits the camera with the mouse, splits two ports A/B (or shows |A - B|)\n"
     "with their RMSE and SSIM against a third, and saves the changes as a graph\n"
     "variant beside FILE.\n"
     "Edits of the graph or its scene on disk reload it. Nothing is written into --out\n"
     "but what compare nodes report. Ends on Ctrl-C (docs/viewer.md)."},
    {SSG_CLI_LAYERS, "layers", "FILE", 1, 1,
     "an image file's layers: channels, size, min/max/mean",
     "Lists the layers of the image FILE (an EXR's named layers, its unnamed channels and\n"
     "its depth Z; any other file: one unnamed layer), a line each: the name that reads\n"
     "it (`ssgraph extract`, `ssgraph node --in PORT=FILE:LAYER`), its channels as the\n"
     "file names them (what oiiotool's --ch wants: ao.Y), its size, and the minimum,\n"
     "maximum and mean of its finite values (and how many are not finite)."},
    {SSG_CLI_EXTRACT, "extract", "FILE LAYER", 2, 2,
     "one layer of an EXR as PNG or EXR (-o OUT.png|OUT.exr)",
     "Writes the layer LAYER of the image FILE to -o OUT.exr (32-bit float: Y, or R,G,B)\n"
     "or OUT.png (the write node's 8-bit sRGB preview, grey for one channel; --tonemap,\n"
     "--exposure). LAYER is a name `ssgraph layers` lists (`(unnamed)`: the unnamed\n"
     "channels) or one channel of it (ao.Y; normal.X: that channel alone). An unknown\n"
     "layer is an error naming the file's layers; no error leaves a file behind."},
    {SSG_CLI_NODES, "nodes", "", 0, 0, "list the nodes",
     "Lists every node type with its one-line summary."},
    {SSG_CLI_DESCRIBE, "describe", "NODE", 1, 1,
     "ports, parameters, defaults, ranges and method of a node",
     "Prints the node's ports, its parameters with types, defaults, ranges and units,\n"
     "and the method it implements, from its descriptor."},
    {SSG_CLI_DOCS, "docs", "[nodes|scenes]", 0, 1,
     "the Markdown reference of every node, or of every scene entity",
     "Prints the Markdown reference of every node (default; docs/nodes.md is this\n"
     "output, run in the repository root: each node lists the graphs/ that use it) or\n"
     "of every scene entity and its parameters (docs/scenes.md)."},
    {SSG_CLI_HELP, "help", "[COMMAND]", 0, 1, "this list, or one command's usage",
     "Without COMMAND: every command and every option. With COMMAND: its usage and\n"
     "only its options (the same as `ssgraph COMMAND --help`)."},
};
const int ssg_cli_command_count = sizeof ssg_cli_commands / sizeof ssg_cli_commands[0];
