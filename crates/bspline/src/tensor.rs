//! Bivariate tensor-product functions (in progress).
