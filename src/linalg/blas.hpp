#pragma once
/// @file blas.hpp
/// The few BLAS routines gapfem calls itself (Fortran interface of the BLAS CHOLMOD links,
/// OpenBLAS on Debian): dense blocks inside the sparse factor's corrections.
extern "C" {
void dtrsm_(const char* side, const char* uplo, const char* transa, const char* diag, const int* m,
            const int* n, const double* alpha, const double* a, const int* lda, double* b,
            const int* ldb);
void dgemm_(const char* transa, const char* transb, const int* m, const int* n, const int* k,
            const double* alpha, const double* a, const int* lda, const double* b, const int* ldb,
            const double* beta, double* c, const int* ldc);
}
