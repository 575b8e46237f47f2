C     A test user element for the Abaqus utility routines gapfem
C     provides: a linear spring of stiffness PROPS(1) between DOF 1 of
C     its two nodes that calls them.
C     PROPS(2) = MODE, PROPS(3) = a displacement limit of node 2:
C       MODE 0: on its first call, writes <outdir>/<job>.utl with what
C               GETJOBNAME, GETOUTDIR, GETNUMCPUS, GETRANK, SINV,
C               SPRINC, SPRIND and ROTSIG return for a fixed tensor,
C               and an informational message (STDB_ABQERR, LOP=1);
C       MODE 1: a warning (LOP=-1) on every call;
C       MODE 2: an error (LOP=-3) once U(2) exceeds the limit;
C       MODE 3: CALL XIT once U(2) exceeds the limit.
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
      DIMENSION INTV(2),REALV(2)
      CHARACTER*8 CHARV(1)
      CHARACTER*256 JOBNAM,OUTDIR
      INTEGER LJOB,LOUT,NCPU,IRANK
      LOGICAL WROTE
      SAVE WROTE
      DATA WROTE /.FALSE./
C
      DO I = 1, NDOFEL
        RHS(I,1) = 0.D0
        DO J = 1, NDOFEL
          AMATRX(I,J) = 0.D0
        END DO
      END DO
      AMATRX(1,1) = PROPS(1)
      AMATRX(2,2) = PROPS(1)
      AMATRX(1,2) = -PROPS(1)
      AMATRX(2,1) = -PROPS(1)
      RHS(1,1) = -PROPS(1)*(U(1) - U(2))
      RHS(2,1) = PROPS(1)*(U(1) - U(2))
      MODE = NINT(PROPS(2))
C
      IF (MODE .EQ. 0 .AND. .NOT. WROTE) THEN
        WROTE = .TRUE.
        CALL GETJOBNAME(JOBNAM, LJOB)
        CALL GETOUTDIR(OUTDIR, LOUT)
        CALL GETNUMCPUS(NCPU)
        CALL GETRANK(IRANK)
        INTV(1) = JELEM
        REALV(1) = PROPS(1)
        CHARV(1) = 'spring'
        CALL STDB_ABQERR(1, '%S %I has stiffness %R', INTV, REALV,
     1   CHARV)
        CALL WRITE_TENSORS(OUTDIR(1:LOUT)//'/'//JOBNAM(1:LJOB)//'.utl',
     1   JOBNAM(1:LJOB), OUTDIR(1:LOUT), LJOB, LOUT, NCPU, IRANK)
      END IF
      IF (MODE .EQ. 1) THEN
        INTV(1) = KINC
        CALL STDB_ABQERR(-1, 'increment %I: spring checked', INTV,
     1   REALV, CHARV)
      END IF
      IF (MODE .GE. 2 .AND. U(2) .GT. PROPS(3)) THEN
        IF (MODE .EQ. 3) CALL XIT
        INTV(1) = JELEM
        REALV(1) = U(2)
        REALV(2) = PROPS(3)
        CALL STDB_ABQERR(-3, 'element %I stretched to %R beyond %R',
     1   INTV, REALV, CHARV)
      END IF
      RETURN
      END
C
C     The utility routines on S = (2, 2, 5, 1, 0, 0) (principal values
C     1, 3, 5) and its strain twin with engineering shear 2, and ROTSIG
C     with a rotation of 90 degrees about z.
      SUBROUTINE WRITE_TENSORS(PATH, JOBNAM, OUTDIR, LJOB, LOUT, NCPU,
     1 IRANK)
      INCLUDE 'ABA_PARAM.INC'
      CHARACTER*(*) PATH, JOBNAM, OUTDIR
      DIMENSION S(6), E(6), PS(3), AN(3,3), R(3,3), SP(6), PE(3), S4(4)
      DIMENSION SP4(4)
      DATA S /2.D0, 2.D0, 5.D0, 1.D0, 0.D0, 0.D0/
      DATA E /2.D0, 2.D0, 5.D0, 2.D0, 0.D0, 0.D0/
      DATA S4 /2.D0, 2.D0, 5.D0, 1.D0/
      DATA R /0.D0, 1.D0, 0.D0, -1.D0, 0.D0, 0.D0, 0.D0, 0.D0, 1.D0/
      OPEN(UNIT=77, FILE=PATH, STATUS='REPLACE')
      WRITE(77,'(A)') JOBNAM
      WRITE(77,'(A)') OUTDIR
      WRITE(77,*) LJOB, LOUT, NCPU, IRANK
      CALL SINV(S, SINV1, SINV2, 3, 3)
      WRITE(77,*) SINV1, SINV2
      CALL SPRINC(S, PS, 1, 3, 3)
      WRITE(77,*) PS
      CALL SPRINC(E, PE, 2, 3, 3)
      WRITE(77,*) PE
      CALL SPRIND(S, PS, AN, 1, 3, 3)
      WRITE(77,*) PS
      WRITE(77,*) ((AN(I,J), J=1,3), I=1,3)
      CALL ROTSIG(S, R, SP, 1, 3, 3)
      WRITE(77,*) SP
      CALL ROTSIG(E, R, SP, 2, 3, 3)
      WRITE(77,*) SP
      CALL ROTSIG(S4, R, SP4, 1, 3, 1)
      WRITE(77,*) SP4
      CLOSE(77)
      RETURN
      END
