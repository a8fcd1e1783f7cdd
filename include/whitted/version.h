/* The library's version, for programs built against it and for tiles. */
#ifndef RT_VERSION_H
#define RT_VERSION_H

#define RT_VERSION "1.0.0"

#endif
