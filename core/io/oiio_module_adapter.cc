// oiio_module_adapter.cc - the entry point of libssgraph_oiio.so (oiio_module.h): checks the ABI,
// keeps the host table and hands out the api table. The only symbol the module exports.
extern "C" {
#include "io/oiio_module.h"
}
#include "io/oiio_host.h"

const struct ssg_oiio_host *ssg_oiio_host_fns;

extern "C" __attribute__((visibility("default"))) const struct ssg_oiio_api *
ssg_oiio_module(int abi, const struct ssg_oiio_host *host)
{
    static const struct ssg_oiio_api api = {ssg_oiio_image_read, ssg_oiio_text_draw};
    if (abi != SSG_OIIO_MODULE_ABI || !host)
        return nullptr;
    ssg_oiio_host_fns = host;
    return &api;
}
