C     A test user element for gapfem's dynamics, written as for
C     Abaqus/Standard: a linear elastic truss between two nodes (DOFs
C     1-3 each) with the lumped mass of the built-in T3D2,
C     RHO*A*L/2 on each translation of each node.
C     PROPS: A, E, RHO.
C     LFLAGS(3) = 1 or 2: RHS = -K U, AMATRX = K (K = EA/L d d^T in
C        the node blocks, d the unit axis); LFLAGS(3) = 4: AMATRX = M.
C     SVARS(1) counts the calls that asked for the mass (they must not
C        change it: gapfem calls with copies).
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
      ALEN = 0.D0
      DO I = 1, 3
        DX(I) = COORDS(I,2) - COORDS(I,1)
        ALEN = ALEN + DX(I)**2
      END DO
      ALEN = SQRT(ALEN)
      DO I = 1, 3
        DX(I) = DX(I)/ALEN
      END DO
C
      IF (LFLAGS(3) .EQ. 4) THEN
        HALF = 0.5D0*PROPS(3)*PROPS(1)*ALEN
        DO I = 1, NDOFEL
          AMATRX(I,I) = HALF
        END DO
        SVARS(1) = SVARS(1) + 1.D0
        RETURN
      END IF
C
      EAL = PROPS(1)*PROPS(2)/ALEN
      DO I = 1, 3
        DO J = 1, 3
          S = EAL*DX(I)*DX(J)
          AMATRX(I,J) = S
          AMATRX(I+3,J+3) = S
          AMATRX(I,J+3) = -S
          AMATRX(I+3,J) = -S
        END DO
      END DO
      DO I = 1, NDOFEL
        DO J = 1, NDOFEL
          RHS(I,1) = RHS(I,1) - AMATRX(I,J)*U(J)
        END DO
      END DO
      RETURN
      END
