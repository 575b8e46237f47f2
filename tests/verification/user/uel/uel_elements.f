C     Test user elements for gapfem, written as for Abaqus/Standard:
C
C     JTYPE 1 (U1): a nonlinear spring between DOF 1 of its two nodes,
C        F = K*D + K3*D**3, D = U(2) - U(1).  PROPS: K, K3.
C        SVARS(1) = the force at the end of the increment.
C
C     JTYPE 2 (U2): a truss between two nodes (DOFs 1-3 each), small strain,
C        elastic-plastic with linear isotropic hardening (return mapping).
C        PROPS: A, E, SIGY, H (plastic modulus), DEPMAX.
C        SVARS: (1) plastic strain, (2) equivalent plastic strain,
C               (3) stress.
C        PNEWDT = 0.5 when the plastic strain grows by more than DEPMAX
C        in one increment (a cut-back the analysis must honour).
C        ENERGY(2): the elastic strain energy.
C
      SUBROUTINE UEL(RHS,AMATRX,SVARS,ENERGY,NDOFEL,NRHS,NSVARS,
     1 PROPS,NPROPS,COORDS,MCRD,NNODE,U,DU,V,A,JTYPE,TIME,DTIME,
     2 KSTEP,KINC,JELEM,PARAMS,NDLOAD,JDLTYP,ADLMAG,PREDEF,NPREDF,
     3 LFLAGS,MLVARX,DDLMAG,MDLOAD,PNEWDT,JPROPS,NJPROP,PERIOD)
C
      INCLUDE 'ABA_PARAM.INC'
C
      DIMENSION RHS(MLVARX,*),AMATRX(NDOFEL,NDOFEL),PROPS(*),
     1 SVARS(*),ENERGY(8),COORDS(MCRD,NNODE),U(NDOFEL),
     2 DU(MLVARX,*),V(NDOFEL),A(NDOFEL),TIME(2),PARAMS(*),
     3 JDLTYP(MDLOAD,*),ADLMAG(MDLOAD,*),DDLMAG(MDLOAD,*),
     4 PREDEF(2,NPREDF,NNODE),LFLAGS(*),JPROPS(*)
      DIMENSION DX(3)
C
      DO I = 1, NDOFEL
        RHS(I,1) = 0.D0
        DO J = 1, NDOFEL
          AMATRX(I,J) = 0.D0
        END DO
      END DO
C
      IF (JTYPE .EQ. 1) THEN
        D = U(2) - U(1)
        F = PROPS(1)*D + PROPS(2)*D**3
        STIFF = PROPS(1) + 3.D0*PROPS(2)*D**2
        RHS(1,1) = F
        RHS(2,1) = -F
        AMATRX(1,1) = STIFF
        AMATRX(2,2) = STIFF
        AMATRX(1,2) = -STIFF
        AMATRX(2,1) = -STIFF
        SVARS(1) = F
        RETURN
      END IF
C
C     truss: unit direction and length from the reference coordinates
      ALEN = 0.D0
      DO I = 1, 3
        DX(I) = COORDS(I,2) - COORDS(I,1)
        ALEN = ALEN + DX(I)**2
      END DO
      ALEN = SQRT(ALEN)
      DO I = 1, 3
        DX(I) = DX(I)/ALEN
      END DO
      EPS = 0.D0
      DO I = 1, 3
        EPS = EPS + DX(I)*(U(3+I) - U(I))
      END DO
      EPS = EPS/ALEN
      AREA = PROPS(1)
      E = PROPS(2)
      SIGY = PROPS(3)
      H = PROPS(4)
C     elastic predictor from the start-of-increment plastic strain
      EP0 = SVARS(1)
      ALPHA0 = SVARS(2)
      SIG = E*(EPS - EP0)
      FY = ABS(SIG) - (SIGY + H*ALPHA0)
      ET = E
      IF (FY .GT. 0.D0) THEN
        DGAM = FY/(E + H)
        SIG = SIG - E*DGAM*SIGN(1.D0, SIG)
        SVARS(1) = EP0 + DGAM*SIGN(1.D0, SIG)
        SVARS(2) = ALPHA0 + DGAM
        ET = E*H/(E + H)
        IF (DGAM .GT. PROPS(5)) PNEWDT = 0.5D0
      END IF
      SVARS(3) = SIG
      F = SIG*AREA
      DO I = 1, 3
        RHS(I,1) = F*DX(I)
        RHS(3+I,1) = -F*DX(I)
        DO J = 1, 3
          T = ET*AREA/ALEN*DX(I)*DX(J)
          AMATRX(I,J) = T
          AMATRX(3+I,3+J) = T
          AMATRX(I,3+J) = -T
          AMATRX(3+I,J) = -T
        END DO
      END DO
      ENERGY(2) = 0.5D0*SIG**2/E*AREA*ALEN
      RETURN
      END
