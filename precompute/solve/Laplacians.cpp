#include "precompute/solve/Laplacians.h"

namespace modeflow {
namespace {

using ColMatrix = Eigen::SparseMatrix<double>;

/// D1 B W Bᵀ D1 for diagonal D1 (rows of B) and W (columns of B).
ColMatrix weightedGram(const SparseMatrix& b, const Eigen::VectorXd& outer,
                       const Eigen::VectorXd& inner) {
    const ColMatrix bc = ColMatrix(b.cast<double>());
    const ColMatrix scaled = outer.asDiagonal() * bc;
    ColMatrix gram = scaled * inner.asDiagonal() * scaled.transpose();
    gram.makeCompressed();
    return gram;
}

}  // namespace

Eigen::SparseMatrix<double> velocityCurlCurl(const CutCellDec& dec) {
    return weightedGram(dec.curl, dec.faceStar, dec.vorticityStarInverse);
}

Eigen::SparseMatrix<double> velocityLaplacian(const CutCellDec& dec, double penalty) {
    const Eigen::VectorXd unit = Eigen::VectorXd::Ones(dec.faces.size());
    const SparseMatrix divT = dec.div.transpose();
    ColMatrix gradDiv = weightedGram(divT, unit, dec.cellStar);
    ColMatrix k = (1.0 + penalty) * gradDiv + velocityCurlCurl(dec);
    k.makeCompressed();
    return k;
}

Eigen::SparseMatrix<double> neumannScalarLaplacian(const CutCellDec& dec) {
    return weightedGram(dec.div, dec.cellStar, dec.faceStar.cwiseInverse());
}

Eigen::SparseMatrix<double> dirichletScalarLaplacian(const DirichletScalarDec& dec) {
    return weightedGram(dec.div, dec.cellStar, dec.faceWeight);
}

}  // namespace modeflow
