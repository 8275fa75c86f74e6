// Copyright (c) 2026  CGAL Qzip contributors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : CGAL Qzip contributors
//
// License check for the Qzip package, following CGAL's generated license headers.

#ifndef CGAL_LICENSE_QZIP_H
#define CGAL_LICENSE_QZIP_H

#include <CGAL/config.h>
#include <CGAL/license.h>

#ifdef CGAL_QZIP_COMMERCIAL_LICENSE

// This package has no commercial license; defining the macro is a user error.
#  error "The Qzip package is distributed under the GPL only; CGAL_QZIP_COMMERCIAL_LICENSE cannot be honoured."

#else // no CGAL_QZIP_COMMERCIAL_LICENSE

#  if defined(CGAL_LICENSE_WARNING)
     CGAL_pragma_warning("Your application is using GPL licensed code from the Qzip package: "
                         "make sure your application complies with the GPL.")
#  endif
#  ifdef CGAL_LICENSE_ERROR
#    error "The macro CGAL_LICENSE_ERROR is defined: you use the GPL licensed Qzip package."
#  endif

#endif // no CGAL_QZIP_COMMERCIAL_LICENSE

#endif // CGAL_LICENSE_QZIP_H
