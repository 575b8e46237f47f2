C     A test user element for gapfem's dynamics, written as for
C     Abaqus/Standard: a linear spring and a linear dashpot in parallel
C     between two nodes along x (DOF 1 at each node), carrying a point
C     mass at its second node.
C     PROPS: K (stiffness), C (damping coefficient), XM (the mass at
C        node 2), BAD (0; otherwise the damping matrix returned holds
C        an infinite entry, for the bad-input test).
C     LFLAGS(3) = 1 or 2: RHS = -K u, AMATRX = K (K = k [1 -1; -1 1]);
C     LFLAGS(3) = 3: AMATRX = C = c [1 -1; -1 1];
C     LFLAGS(3) = 4: AMATRX = diag(0, XM).
C     gapfem applies inertia and damping itself and calls the residual
C     as in a static step (LFLAGS(1) = 1): a call for the residual
C     with LFLAGS(1) = 11 or 12 (where Abaqus/Standard would expect
C     M a + C v in RHS) sets PNEWDT = -1, which stops the run.
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
C
      DO I = 1, NDOFEL
        RHS(I,1) = 0.D0
        DO J = 1, NDOFEL
          AMATRX(I,J) = 0.D0
        END DO
      END DO
C
      IF (LFLAGS(3) .EQ. 4) THEN
        AMATRX(2,2) = PROPS(3)
        RETURN
      END IF
C
      IF (LFLAGS(3) .EQ. 3) THEN
        AMATRX(1,1) = PROPS(2)
        AMATRX(2,2) = PROPS(2)
        AMATRX(1,2) = -PROPS(2)
        AMATRX(2,1) = -PROPS(2)
        IF (PROPS(4) .NE. 0.D0) THEN
          AMATRX(2,2) = PROPS(4)/(PROPS(4) - PROPS(4))
        END IF
        RETURN
      END IF
C
      IF (LFLAGS(3) .EQ. 1 .AND. LFLAGS(1) .GE. 11
     1    .AND. LFLAGS(1) .LE. 12) THEN
        PNEWDT = -1.D0
      END IF
      AMATRX(1,1) = PROPS(1)
      AMATRX(2,2) = PROPS(1)
      AMATRX(1,2) = -PROPS(1)
      AMATRX(2,1) = -PROPS(1)
      RHS(1,1) = -PROPS(1)*(U(1) - U(2))
      RHS(2,1) = -PROPS(1)*(U(2) - U(1))
      ENERGY(2) = 0.5D0*PROPS(1)*(U(2) - U(1))**2
      RETURN
      END
